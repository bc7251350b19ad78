#include "panels/chart_draw.hpp"

namespace sw::vis {

void paint_chart(ImDrawList* dl, const Chart& c, ImVec2 o, ImFont* font) {
  if (!font) font = ImGui::GetFont();
  auto at = [&](float x, float y) { return ImVec2(o.x + x, o.y + y); };
  dl->PushClipRect(o, at(c.width, c.height), true);
  dl->AddRectFilled(o, at(c.width, c.height), c.background);
  for (const ChartItem& it : c.items) {
    switch (it.kind) {
      case ChartItem::Kind::line: dl->AddLine(at(it.x0, it.y0), at(it.x1, it.y1), it.rgba, it.size); break;
      case ChartItem::Kind::rect: dl->AddRect(at(it.x0, it.y0), at(it.x1, it.y1), it.rgba, 0, 0, it.size); break;
      case ChartItem::Kind::fill_rect: dl->AddRectFilled(at(it.x0, it.y0), at(it.x1, it.y1), it.rgba); break;
      case ChartItem::Kind::marker: {
        const ImVec2 p = at(it.x0, it.y0);
        const float r = it.size;
        constexpr ImU32 kEdge = IM_COL32(0, 0, 0, 255);
        switch (it.shape) {
          case ChartItem::Shape::circle:
            dl->AddCircleFilled(p, r, it.rgba, 20);
            dl->AddCircle(p, r, kEdge, 20, 1);
            break;
          case ChartItem::Shape::square:
            dl->AddRectFilled(ImVec2(p.x - r, p.y - r), ImVec2(p.x + r, p.y + r), it.rgba);
            dl->AddRect(ImVec2(p.x - r, p.y - r), ImVec2(p.x + r, p.y + r), kEdge);
            break;
          case ChartItem::Shape::diamond: {
            const float d = r * 1.25f;
            dl->AddQuadFilled(ImVec2(p.x, p.y - d), ImVec2(p.x + d, p.y), ImVec2(p.x, p.y + d), ImVec2(p.x - d, p.y), it.rgba);
            dl->AddQuad(ImVec2(p.x, p.y - d), ImVec2(p.x + d, p.y), ImVec2(p.x, p.y + d), ImVec2(p.x - d, p.y), kEdge);
            break;
          }
          case ChartItem::Shape::triangle: {
            const ImVec2 a(p.x, p.y - r * 1.3f), b(p.x + r * 1.2f, p.y + r * 0.8f), d(p.x - r * 1.2f, p.y + r * 0.8f);
            dl->AddTriangleFilled(a, b, d, it.rgba);
            dl->AddTriangle(a, b, d, kEdge);
            break;
          }
        }
        break;
      }
      case ChartItem::Kind::text: {
        const float w = font->CalcTextSizeA(it.size, FLT_MAX, 0, it.text.c_str()).x;
        const float x = it.anchor < 0 ? it.x0 : it.anchor == 0 ? it.x0 - w / 2 : it.x0 - w;
        dl->AddText(font, it.size, at(x, it.y0), it.rgba, it.text.c_str());
        break;
      }
    }
  }
  dl->PopClipRect();
}

}  // namespace sw::vis
