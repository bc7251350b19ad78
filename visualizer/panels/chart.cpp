// The accuracy chart's layout (pure arithmetic, no ImGui) and its SVG painter.
#include "panels/chart.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include "bench_text.hpp"

namespace sw::vis {
namespace {

constexpr std::uint32_t rgba(int r, int g, int b, int a = 255) { return std::uint32_t(r) | std::uint32_t(g) << 8 | std::uint32_t(b) << 16 | std::uint32_t(a) << 24; }

constexpr std::uint32_t kBg = rgba(24, 26, 33), kAxis = rgba(150, 156, 175), kGrid = rgba(60, 66, 82), kText = rgba(225, 228, 235),
                        kDimText = rgba(160, 166, 185), kPlotBg = rgba(30, 33, 42);

std::string fmt(const char* f, double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string tick_label(int decade) {
  const double v = std::pow(10.0, decade);
  if (decade >= 6 || decade <= -4) return "1e" + std::to_string(decade);
  return fmt("%g", v);
}

struct Layout {
  Chart c;
  void line(float x0, float y0, float x1, float y1, std::uint32_t col, float w, std::string role = {}) {
    c.items.push_back({ChartItem::Kind::line, x0, y0, x1, y1, col, w, {}, -1, {}, std::move(role)});
  }
  void rect(float x0, float y0, float x1, float y1, std::uint32_t col, bool fill, std::string role = {}) {
    c.items.push_back({fill ? ChartItem::Kind::fill_rect : ChartItem::Kind::rect, x0, y0, x1, y1, col, 1, {}, -1, {}, std::move(role)});
  }
  void text(float x, float y, std::string s, float size, std::uint32_t col, int anchor, std::string role = {}) {
    c.items.push_back({ChartItem::Kind::text, x, y, x, y, col, size, {}, anchor, std::move(s), std::move(role)});
  }
  void marker(float x, float y, float r, Numeric n, std::string role) {
    c.items.push_back({ChartItem::Kind::marker, x, y, x, y, mode_colour(n), r, mode_shape(n), -1, {}, std::move(role)});
  }
};

// One set's panel in the box (x0, y0)-(x1, y1).
void panel(Layout& L, std::string_view alg_id, const std::string& set, const std::vector<const BenchRow*>& rows, float x0, float y0, float x1,
           float y1) {
  const std::size_t cases = rows.empty() ? 0 : rows.front()->cases, full = rows.empty() ? 0 : rows.front()->full_cases;
  const Numeric judge = rows.empty() ? Numeric::exact : rows.front()->judge;
  const std::string count = std::to_string(cases) + (cases < full ? " of " + std::to_string(full) : "") + " cases";
  L.text((x0 + x1) / 2, y0, std::string(alg_id) + ", set " + set + " (" + count + ")", 15, kText, 0, "title set " + set);
  // Plot area: room for the y label above, tick labels left and below, the x label under those.
  const float px0 = x0 + 52, px1 = x1 - 12, py0 = y0 + 44, py1 = y1 - 42;
  if (px1 - px0 < 40 || py1 - py0 < 40) return;
  L.rect(px0, py0, px1, py1, kPlotBg, true);
  L.text(px0 - 44, y0 + 22, "cases differing from " + std::string(judge_name(judge)) + " (%)", 13, kDimText, -1, "axis-label y");
  L.text((px0 + px1) / 2, py1 + 22, std::string(kBenchTimeLabel) + ", log scale", 13, kDimText, 0, "axis-label x");

  double lo = 1e300, hi = 0, top = 0;
  for (const BenchRow* r : rows) {
    const double ns = std::max(r->ns_per_op, 1e-3);
    lo = std::min(lo, ns), hi = std::max(hi, ns);
    if (r->cases) top = std::max(top, 100.0 * double(r->mismatches) / double(r->cases));
  }
  if (rows.empty()) lo = 1, hi = 10;
  int d0 = int(std::floor(std::log10(lo) - 0.1)), d1 = int(std::ceil(std::log10(hi) + 0.1));
  if (d1 <= d0) d1 = d0 + 1;
  const double ymax = std::min(100.0, nice_ceil(std::max(top * 1.1, 1.0)));
  const float inset = 8;  // markers at 0% or at a decade sit off the frame
  auto sx = [&](double ns) { return float(px0 + (px1 - px0) * (std::log10(std::max(ns, 1e-3)) - d0) / double(d1 - d0)); };
  auto sy = [&](double pct) { return float(py1 - inset - (py1 - py0 - 2 * inset) * pct / ymax); };

  for (int d = d0; d <= d1; ++d) {  // decades labelled, 2..9 times as short ticks
    const float x = sx(std::pow(10.0, d));
    L.line(x, py0, x, py1, kGrid, 1);
    L.line(x, py1, x, py1 + 5, kAxis, 1, "tick x");
    L.text(x, py1 + 6, tick_label(d), 12, kDimText, 0, "tick-label x");
    for (int m = 2; m <= 9 && d < d1; ++m) {
      const float xm = sx(m * std::pow(10.0, d));
      L.line(xm, py1, xm, py1 + 3, kAxis, 1);
    }
  }
  for (int k = 0; k <= 5; ++k) {
    const double v = ymax * k / 5;
    const float y = sy(v);
    L.line(px0, y, px1, y, kGrid, 1);
    L.line(px0 - 5, y, px0, y, kAxis, 1, "tick y");
    L.text(px0 - 7, y - 7, fmt("%g", v), 12, kDimText, 1, "tick-label y");
  }
  L.line(px0, py1, px1, py1, kAxis, 1.5f, "axis x");
  L.line(px0, py0, px0, py1, kAxis, 1.5f, "axis y");

  // Markers, then their labels where they do not cover one already placed.
  std::vector<std::array<float, 4>> placed;  // markers first: no label covers one
  auto pct_of = [](const BenchRow* r) { return r->cases ? 100.0 * double(r->mismatches) / double(r->cases) : 0.0; };
  for (const BenchRow* r : rows) {
    const float x = sx(r->ns_per_op), y = sy(pct_of(r));
    L.marker(x, y, 6, r->numeric, "marker " + std::string(numeric_name(r->numeric)) + " " + set);
    placed.push_back({x - 8, y - 8, x + 8, y + 8});
  }
  for (const BenchRow* r : rows) {
    const double pct = pct_of(r);
    const float x = sx(r->ns_per_op), y = sy(pct);
    std::string label = std::string(numeric_name(r->numeric)) + " " + fmt(pct >= 10 || pct == 0 ? "%.0f%%" : "%.2g%%", pct);
    if (r->max_error > 0) label += ", max error " + fmt("%.3g", r->max_error) + " " + std::string(r->error_unit);
    const float w = chart_text_width(label, 12);
    const bool left = x + 10 + w > px1;
    for (float dy : {-7.f, 7.f, -21.f, 21.f}) {
      const float lx = left ? x - 10 - w : x + 10, ly = y + dy - (dy < 0 ? 0 : 7);
      const std::array<float, 4> box{lx, ly, lx + w, ly + 13};
      const bool covers = std::any_of(placed.begin(), placed.end(), [&](const auto& q) { return box[0] < q[2] && q[0] < box[2] && box[1] < q[3] && q[1] < box[3]; });
      if (covers || ly < py0 || ly + 13 > py1) continue;
      placed.push_back(box);
      L.text(left ? x - 10 : x + 10, ly, label, 12, mode_colour(r->numeric), left ? 1 : -1, "marker-label " + std::string(numeric_name(r->numeric)));
      break;
    }
  }
}

}  // namespace

float chart_text_width(std::string_view text, float size) { return float(text.size()) * size * 0.55f; }

std::uint32_t mode_colour(Numeric n) {
  switch (n) {
    case Numeric::f32: return rgba(255, 150, 60);
    case Numeric::f64: return rgba(90, 170, 255);
    case Numeric::integer: return rgba(120, 220, 120);
    case Numeric::filtered: return rgba(200, 130, 255);
    case Numeric::exact: return rgba(240, 240, 240);
    case Numeric::reference: return rgba(80, 220, 210);
  }
  return kText;
}

ChartItem::Shape mode_shape(Numeric n) {
  constexpr ChartItem::Shape kShapes[] = {ChartItem::Shape::circle, ChartItem::Shape::square, ChartItem::Shape::diamond, ChartItem::Shape::triangle};
  return kShapes[static_cast<int>(n) % 4];
}

Chart bench_chart(std::string_view alg_id, const std::vector<BenchRow>& rows, float width, float height, std::string_view note) {
  Layout L;
  L.c.width = width, L.c.height = height, L.c.background = kBg;
  L.text(width / 2, 12, std::string(alg_id) + ": the cost of accuracy", 20, kText, 0, "title");
  L.text(width / 2, 38, note.empty() ? bench_chart_note(rows, 0) : std::string(note), 13, kDimText, 0, "note");
  std::vector<std::string> sets;
  std::vector<Numeric> modes;
  for (const BenchRow& r : rows) {
    if (std::find(sets.begin(), sets.end(), r.set) == sets.end()) sets.push_back(r.set);
    if (std::find(modes.begin(), modes.end(), r.numeric) == modes.end()) modes.push_back(r.numeric);
  }
  if (sets.empty()) {
    L.text(width / 2, height / 2, "no measurements", 15, kDimText, 0, "empty");
    return L.c;
  }
  // Legend along the bottom, centred.
  float legend_w = 0;
  for (Numeric n : modes) legend_w += 22 + chart_text_width(numeric_name(n), 13) + 18;
  float lx = std::max(16.f, (width - legend_w) / 2);
  const float ly = height - 26;
  for (Numeric n : modes) {
    L.marker(lx + 6, ly + 8, 6, n, "legend " + std::string(numeric_name(n)));
    L.text(lx + 18, ly, std::string(numeric_name(n)), 13, kText, -1, "legend-label");
    lx += 22 + chart_text_width(numeric_name(n), 13) + 18;
  }
  // Panels in a grid: up to three side by side.
  const int cols = int(std::min<std::size_t>(sets.size(), 3)), grid_rows = int((sets.size() + std::size_t(cols) - 1) / std::size_t(cols));
  const float top = 62, bottom = height - 36, pw = (width - 16) / float(cols), ph = (bottom - top) / float(grid_rows);
  for (std::size_t s = 0; s < sets.size(); ++s) {
    std::vector<const BenchRow*> mine;
    for (const BenchRow& r : rows)
      if (r.set == sets[s]) mine.push_back(&r);
    const float x0 = 8 + pw * float(s % std::size_t(cols)), y0 = top + ph * float(s / std::size_t(cols));
    panel(L, alg_id, sets[s], mine, x0, y0, x0 + pw, y0 + ph);
  }
  return L.c;
}

namespace {

// what="rgb(r,g,b)" what-opacity="a", for what = fill or stroke.
std::string paint(const char* what, std::uint32_t c) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s=\"rgb(%u,%u,%u)\" %s-opacity=\"%.3f\"", what, c & 255u, (c >> 8) & 255u, (c >> 16) & 255u, what,
                double((c >> 24) & 255u) / 255.0);
  return buf;
}

std::string escape(std::string_view t) {
  std::string out;
  for (char ch : t) {
    if (ch == '&') out += "&amp;";
    else if (ch == '<') out += "&lt;";
    else if (ch == '>') out += "&gt;";
    else if (ch == '"') out += "&quot;";
    else out += ch;
  }
  return out;
}

}  // namespace

std::string chart_svg(const Chart& c) {
  std::ostringstream o;
  o.precision(6);
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << c.width << "\" height=\"" << c.height << "\" viewBox=\"0 0 " << c.width << ' ' << c.height
    << "\" font-family=\"DejaVu Sans, Verdana, sans-serif\">\n"
    << "<rect x=\"0\" y=\"0\" width=\"" << c.width << "\" height=\"" << c.height << "\" " << paint("fill", c.background) << "/>\n";
  for (const ChartItem& it : c.items) {
    const std::string cls = it.role.empty() ? "" : " class=\"" + escape(it.role) + "\"";
    switch (it.kind) {
      case ChartItem::Kind::line:
        o << "<line x1=\"" << it.x0 << "\" y1=\"" << it.y0 << "\" x2=\"" << it.x1 << "\" y2=\"" << it.y1 << "\" " << paint("stroke", it.rgba)
          << " stroke-width=\"" << it.size << "\"" << cls << "/>\n";
        break;
      case ChartItem::Kind::rect:
      case ChartItem::Kind::fill_rect:
        o << "<rect x=\"" << it.x0 << "\" y=\"" << it.y0 << "\" width=\"" << it.x1 - it.x0 << "\" height=\"" << it.y1 - it.y0 << "\" "
          << (it.kind == ChartItem::Kind::rect ? paint("stroke", it.rgba) + " fill=\"none\"" : paint("fill", it.rgba)) << cls << "/>\n";
        break;
      case ChartItem::Kind::marker: {  // a group at the marker's centre: its data point
        const float r = it.size;
        o << "<g" << cls << " transform=\"translate(" << it.x0 << ',' << it.y0 << ")\">";
        const std::string style = paint("fill", it.rgba) + " stroke=\"black\" stroke-width=\"1\"";
        if (it.shape == ChartItem::Shape::circle) o << "<circle cx=\"0\" cy=\"0\" r=\"" << r << "\" " << style << "/>";
        else if (it.shape == ChartItem::Shape::square) o << "<rect x=\"" << -r << "\" y=\"" << -r << "\" width=\"" << 2 * r << "\" height=\"" << 2 * r << "\" " << style << "/>";
        else if (it.shape == ChartItem::Shape::diamond)
          o << "<polygon points=\"0," << -r * 1.25f << ' ' << r * 1.25f << ",0 0," << r * 1.25f << ' ' << -r * 1.25f << ",0\" " << style << "/>";
        else o << "<polygon points=\"0," << -r * 1.3f << ' ' << r * 1.2f << ',' << r * 0.8f << ' ' << -r * 1.2f << ',' << r * 0.8f << "\" " << style << "/>";
        o << "</g>\n";
        break;
      }
      case ChartItem::Kind::text: {
        // The layout's y is the text's top and its size ImGui's (ascent - descent): DejaVu's em is
        // 0.86 of that and its baseline 0.8 below the top.
        const char* anchor = it.anchor < 0 ? "start" : it.anchor == 0 ? "middle" : "end";
        o << "<text x=\"" << it.x0 << "\" y=\"" << it.y0 + 0.8f * it.size << "\" font-size=\"" << 0.86f * it.size << "\" text-anchor=\"" << anchor << "\" "
          << paint("fill", it.rgba) << " stroke=\"none\"" << cls << '>' << escape(it.text) << "</text>\n";
        break;
      }
    }
  }
  o << "</svg>\n";
  return o.str();
}

std::string bench_chart_note(const std::vector<BenchRow>& rows, int repeats, bool quick) {
  const BenchSummary sum = bench_summary(rows, quick);
  std::string s = repeats <= 0 ? "" : repeats_text(repeats, quick) + " per mode; ";
  s += "y: cases whose output differs from " + std::string(judge_text(sum.judge));
  if (!sum.error_unit.empty()) s += "; max error in " + std::string(sum.error_unit);
  return s;
}

double nice_ceil(double v) {
  const double p = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * p >= v * (1 - 1e-12)) return m * p;
  return 10 * p;
}

}  // namespace sw::vis
