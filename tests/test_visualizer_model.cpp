// The visualizer's model, without GL: lessons, the trace indexes, the incremental pixel texture
// and the float-against-exact comparison.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <set>
#include <random>
#include "lessons/compare.hpp"
#include "cli_harness.hpp"
#include "fill_oracle.hpp"
#include "lessons/lesson.hpp"
#include "panels/pixel_layer.hpp"
#include "spatial/ray_triangles.hpp"
#include "lessons/trace_model.hpp"

using namespace sw;
using namespace sw::vis;

namespace {

// A texture host in memory: what the GPU would hold.
class MemoryTextures final : public TextureHost {
 public:
  ImTextureID create(int w, int h) override {
    images_[++next_] = {w, h, std::vector<std::uint32_t>(std::size_t(w) * h, 0xdeadbeef)};
    return reinterpret_cast<ImTextureID>(next_);
  }
  void update(ImTextureID t, int x, int y, int w, int h, const std::uint32_t* rgba, int stride) override {
    Image& im = images_.at(reinterpret_cast<std::intptr_t>(t));
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) im.px[std::size_t(y + r) * im.w + x + c] = rgba[std::size_t(r) * stride + c];
    updated_texels_ += std::size_t(w) * h;
  }
  void destroy(ImTextureID t) override { images_.erase(reinterpret_cast<std::intptr_t>(t)); }
  struct Image {
    int w, h;
    std::vector<std::uint32_t> px;
  };
  const Image& image(ImTextureID t) const { return images_.at(reinterpret_cast<std::intptr_t>(t)); }
  std::size_t updated_texels_ = 0;

 private:
  std::map<std::intptr_t, Image> images_;
  std::intptr_t next_ = 0;
};

std::shared_ptr<const TraceModel> dda(const char* input, Numeric n = Numeric::exact, const char* alg = "dda-line") {
  return record_model(find_algorithm(alg), parse_json_text(input, "test"), n);
}

// The texel colour each cell must have at `step`, computed from the trace directly.
std::uint32_t expected_colour(const TraceModel& m, Pixel c, std::size_t step) {
  std::uint32_t first = kNoStep;
  for (const PlotEvent& e : m.plots())
    if (e.cell == c && e.step <= step) first = std::min(first, e.step);
  return first == kNoStep ? 0u : plot_colour(first, m.last());
}

void check_texture(const MemoryTextures& tex, const PixelLayer& layer, const TraceModel& m, std::size_t step) {
  const CellWindow& w = layer.window();
  REQUIRE(w.k == 1);
  const auto& im = tex.image(layer.texture());
  for (int v = 0; v < w.h; ++v)
    for (int u = 0; u < w.w; ++u) {
      const Pixel c{w.x0 + u, w.y0 + (w.h - 1 - v)};
      INFO("cell " << c.x << "," << c.y << " step " << step);
      REQUIRE(im.px[std::size_t(v) * w.w + u] == expected_colour(m, c, step));
    }
}

}  // namespace

TEST_CASE("visualizer lesson: front matter, narration keys and the manifest", "[visualizer][lesson]") {
  const Lesson l = parse_lesson(
      "---\ntitle: T\nalgorithm: dda-line\ninput: {\"p0\":[0,0],\"p1\":[5,2]}\nnumeric: exact\ncompare: float\nstep: 3\n---\n"
      "Intro text.\n\n## on line plot\nPlot here.\n## on kind advance\nMove.\n",
      "t.md");
  CHECK(l.title == "T");
  CHECK(l.algorithm->id == "dda-line");
  CHECK(l.numeric == Numeric::exact);
  REQUIRE(l.compare);
  CHECK(l.compare.numeric == Numeric::f32);
  CHECK(l.compare.other == nullptr);
  CHECK(l.start_step == 3);
  CHECK(l.intro == "Intro text.");
  REQUIRE(l.sections.size() == 2);
  CHECK(l.sections[0].key == Narration::Key::line);
  CHECK(l.sections[1].key == Narration::Key::kind);

  const auto files = lesson_manifest(std::filesystem::path(SW_SOURCE_DIR) / "lessons");
  REQUIRE(files.size() >= 3);
  for (const auto& f : files) {
    INFO(f);
    const Lesson lesson = load_lesson(f);
    CHECK(!lesson.sections.empty());
    auto png = f;
    CHECK(std::filesystem::exists(png.replace_extension(".png")));  // one screenshot per lesson
  }
}

TEST_CASE("visualizer lesson: malformed lessons name the problem and the place", "[visualizer][lesson]") {
  auto error_of = [](const std::string& text) {
    try {
      (void)parse_lesson(text, "bad.md");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string head = "---\nalgorithm: dda-line\n";
  CHECK_THAT(error_of("no front matter\n"), Catch::Contains("bad.md:1") && Catch::Contains("---"));
  CHECK_THAT(error_of(head + "input: {\"p0\":[0,0],\"p1\":[5,2]}\n"), Catch::Contains("no closing"));
  CHECK_THAT(error_of(head + "colour: red\n---\n"), Catch::Contains("bad.md:3") && Catch::Contains("colour"));
  CHECK_THAT(error_of("---\nalgorithm: dda-circle\ninput: {}\n---\n"), Catch::Contains("unknown algorithm 'dda-circle'"));
  CHECK_THAT(error_of(head + "input: {\"p0\":[0,0]}\n---\n"), Catch::Contains("bad.md:3") && Catch::Contains("p1"));
  CHECK_THAT(error_of(head + "input: {\"p0\":[0,0],\"p1\":[5,\n---\n"), Catch::Contains("malformed JSON"));
  CHECK_THAT(error_of(head + "input: {\"p0\":[0,0],\"p1\":[5,2]}\nnumeric: int\n---\n"), Catch::Contains("does not run on 'int'"));
  CHECK_THAT(error_of(head + "input: {\"p0\":[0,0],\"p1\":[5,2]}\n---\n## on line 99\nx\n"), Catch::Contains("bad.md:5") && Catch::Contains("not a listing line"));
  CHECK_THAT(error_of(head + "input: {\"p0\":[0,0],\"p1\":[5,2]}\n---\n## on kind jump\nx\n"), Catch::Contains("unknown step kind"));
  CHECK_THAT(error_of(head + "---\n"), Catch::Contains("input"));
  CHECK_THAT(error_of(head + "input: {\"p0\":[0,0],\"p1\":[5,2]}\nshow: tree\n---\n"), Catch::Contains("bad.md:4") && Catch::Contains("dda-line declares plane2d"));
}

TEST_CASE("visualizer lesson: show opens a declared view, and a relative mesh is found beside the lesson", "[visualizer][lesson]") {
  const auto dir = sw::testing::scratch("lesson");
  std::filesystem::create_directories(dir / "m");
  std::ofstream(dir / "m" / "t.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  std::ofstream(dir / "l.md") << "---\nalgorithm: bvh-build\ninput: {\"mesh\":\"m/t.off\"}\nshow: orbit3d\n---\nIntro.\n";
  const Lesson l = load_lesson(dir / "l.md");
  REQUIRE(l.show);
  CHECK(*l.show == View::orbit3d);
  CHECK(l.input["mesh"] == (dir / "m" / "t.off").lexically_normal().string());
}

TEST_CASE("visualizer model: plot order, cell lookup and state with changes", "[visualizer][model]") {
  const auto m = dda(R"({"p0":[1.25,2.5],"p1":[12.75,7.25]})");
  REQUIRE(m->plots().size() == 11);
  for (std::size_t k = 0; k < m->plots().size(); ++k) {
    const PlotEvent& e = m->plots()[k];
    CHECK(m->trace().at(e.step).kind == StepKind::plot);
    CHECK(m->step_of_cell(e.cell) == e.step);
    CHECK(m->plots_through(e.step) == k + 1);
    CHECK(m->plots_through(e.step - 1) == k);
  }
  CHECK(m->step_of_cell({100, 100}) == kNoStep);
  // Step 4 is the start offset: dp0 and q are new, dx is old; exact values are p/q text.
  const auto st = m->state_at(4);
  auto var = [&](std::string_view n) {
    for (const VarState& v : st)
      if (v.name == n) return v;
    FAIL("no variable " << n);
    return VarState{};
  };
  CHECK(var("dp0y").text == "57/184");
  CHECK(var("dp0y").changed);
  CHECK(var("qy").text == "517/184");
  CHECK_FALSE(var("dx").changed);
  CHECK_FALSE(var("dx").set_here);
  CHECK(var("dx").text == "23/2");
  // Through the checkpoints: the state at a late step of a long trace equals a plain scan.
  const auto long_line = dda(R"({"p0":[0.5,0.25],"p1":[900.5,301.25]})", Numeric::f64);
  const std::size_t s = 1537;
  std::map<std::string_view, std::string> scan;
  for (std::size_t i = 0; i <= s; ++i)
    for (auto v = long_line->trace().at(i).var_begin; v < long_line->trace().at(i).var_end; ++v)
      scan[long_line->trace().var_at(v).name] = long_line->trace().value_text(long_line->trace().var_at(v));
  const auto late = long_line->state_at(s);
  REQUIRE(late.size() == scan.size());
  for (const VarState& v : late) CHECK(scan[v.name] == v.text);
  CHECK(long_line->find_kind(s, StepKind::plot, true).value() > s);
  CHECK(long_line->find_kind(s, StepKind::done, false) == std::nullopt);
}

TEST_CASE("visualizer model: a vector's difference between two runs is its largest component's", "[visualizer][model]") {
  // transform with the near plane at 1/100: float's window depth differs from exact's in z only.
  const Json in = parse_json_text(R"({"camera":{"eye":[0,0,5],"target":[0,0,0],"up":[0,1,0]},"projection":{"perspective":[-0.01,0.01,-0.01,0.01,0.01,100]},"viewport":[0,0,640,480],"points":[[0,0,-90]]})", "t");
  const auto f = record_model(find_algorithm("transform"), in, Numeric::f32), e = record_model(find_algorithm("transform"), in, Numeric::exact);
  auto var = [](const std::vector<VarState>& st, std::string_view n) {
    for (const VarState& v : st)
      if (v.name == n) return v;
    FAIL("no variable " << n);
    return VarState{};
  };
  const VarState a = var(f->state_at(f->last()), "win"), b = var(e->state_at(e->last()), "win");
  REQUIRE(a.parts.size() == 3);
  REQUIRE(b.parts.size() == 3);
  CHECK(a.parts[0] == b.parts[0]);  // x and y agree: the first component alone would say 0
  const double dz = std::fabs(a.parts[2] - b.parts[2]);
  CHECK(dz > 0);
  CHECK(value_difference(a, b) == std::max({std::fabs(a.parts[0] - b.parts[0]), std::fabs(a.parts[1] - b.parts[1]), dz}));
  VarState shorter = b;
  shorter.parts.pop_back();
  CHECK(value_difference(a, shorter) == std::nullopt);
  VarState nan = b;
  nan.parts[1] = std::nan("");
  CHECK(std::isnan(*value_difference(a, nan)));
}

TEST_CASE("visualizer model: geometry lifetimes keep, replace and end with the step", "[visualizer][model]") {
  // ray-box: the ray and the box are kept from step 0; each clip step keeps its axis' slab and
  // replaces the running [t_near, t_far]; the hit point lives on its own step only.
  const auto m = record_model(find_algorithm("ray-box"), parse_json_text(R"({"ray":{"o":[-3,0.5,0.5],"d":[1,0.125,0.0625]},"box":{"min":[0,0,0],"max":[1,1,1]}})", "t"), Numeric::exact);
  const TraceView& t = m->trace();
  auto labels_at = [&](std::size_t step) {
    std::multiset<std::string> out;
    for (std::uint32_t g : m->visible_items(step)) {
      const GeoRecord& geo = t.geo_at(g);
      out.insert(std::string(geo_name(geo.kind)) + ":" + (geo.label ? geo.label : ""));
    }
    return out;
  };
  using Set = std::multiset<std::string>;
  REQUIRE(m->size() == 5);  // init, three clips, hit
  CHECK(labels_at(0) == Set{"ray:", "box:"});
  CHECK(labels_at(1) == Set{"ray:", "box:", "segment3:x slab", "segment3:[t_near, t_far]"});
  CHECK(labels_at(3) == Set{"ray:", "box:", "segment3:x slab", "segment3:y slab", "segment3:z slab", "segment3:[t_near, t_far]"});
  CHECK(labels_at(4) == Set{"ray:", "box:", "segment3:x slab", "segment3:y slab", "segment3:z slab", "segment3:[t_near, t_far]", "point3:hit"});
  // The interval shown at step k is the one step k recorded (its value t_far - t_near = 1 at the end: t in [3, 4]).
  for (std::size_t s = 1; s <= 3; ++s)
    for (std::uint32_t g : m->visible_items(s))
      if (t.geo_at(g).label && std::string(t.geo_at(g).label) == "[t_near, t_far]") CHECK(g >= t.at(s).geo_begin);
  const auto last = m->visible_items(3);
  for (std::uint32_t g : last)
    if (t.geo_at(g).label && std::string(t.geo_at(g).label) == "[t_near, t_far]") CHECK(*t.geo_value(t.geo_at(g)) == 1);
}

TEST_CASE("visualizer model: stepping over nested calls", "[visualizer][model]") {
  // ray-triangles tests two triangles, each inside the watertight test's nested listing: from the
  // first `test` step (scope 0) the step over lands on the next step of its own listing, after
  // every step of the callee; back over returns to it.
  const auto m = record_model(find_algorithm("ray-triangles"),
                              parse_json_text(R"({"triangles":[[[0,0,0],[1,0,0],[0,1,0]],[[0,0,1],[1,0,1],[0,1,1]]],"ray":{"o":[0.25,0.25,-1],"d":[0,0,1]},"test":"watertight"})", "t"),
                              Numeric::exact);
  const TraceView& t = m->trace();
  std::size_t first_test = 0;
  while (t.at(first_test).scope != 0 || t.at(first_test).line != spatial::RayTriangles::test) ++first_test;
  REQUIRE(t.at(first_test + 1).scope != 0);  // the callee's steps follow
  const auto over = m->step_over(first_test, true);
  REQUIRE(over);
  CHECK(t.at(*over).scope == 0);
  for (std::size_t s = first_test + 1; s < *over; ++s) CHECK(t.at(s).scope != 0);
  CHECK(m->step_over(*over, false) == first_test);
  // From inside the callee, the next step of the callee's listing.
  const auto inner = m->step_over(first_test + 1, true);
  REQUIRE(inner);
  CHECK(*inner == first_test + 2);
  CHECK_FALSE(m->step_over(m->last(), true));
}

TEST_CASE("visualizer texture: scrubbing updates the texture incrementally and exactly", "[visualizer][texture]") {
  const auto m = dda(R"({"p0":["1/3","1/7"],"p1":[40.5,17.25]})", Numeric::exact, "dda-grid-walk");
  MemoryTextures tex;
  PixelLayer layer(tex);
  const WorldRect view{-3, -3, 45, 22};
  REQUIRE(layer.prepare(m, view, 10.0, 0));
  check_texture(tex, layer, *m, 0);
  std::mt19937 rng(11);
  for (int i = 0; i < 40; ++i) {
    const std::size_t step = rng() % m->size();
    tex.updated_texels_ = 0;
    REQUIRE(layer.prepare(m, view, 10.0, step));
    check_texture(tex, layer, *m, step);
  }
  // One step forward touches at most the texels of the pixels that step plotted.
  const std::size_t at = m->plots()[10].step;
  layer.prepare(m, view, 10.0, at - 1);
  tex.updated_texels_ = 0;
  layer.prepare(m, view, 10.0, at);
  CHECK(tex.updated_texels_ == 1);
  check_texture(tex, layer, *m, at);
}

TEST_CASE("visualizer compare: float drifts from exact on a long DDA line", "[visualizer][compare]") {
  const char* in = R"({"p0":["1/10","1/3"],"p1":["3000.3","1000.7"]})";
  const auto f = dda(in, Numeric::f32), e = dda(in, Numeric::exact);
  const CompareStats st = compare_traces(*f, *e);
  CHECK(st.steps_a == st.steps_b);
  CHECK(st.pixels_a == 3000);
  CHECK(st.pixel_mismatches > 0);
  REQUIRE(st.first_decision_divergence);
  REQUIRE(st.first_value_divergence);
  CHECK(*st.first_value_divergence <= *st.first_decision_divergence);
  // Before the divergence every pixel agrees; at it, the plotted pixels differ.
  const std::size_t d = *st.first_decision_divergence;
  CHECK(f->pixel_at(d) != e->pixel_at(d));
  for (std::size_t s = 0; s < d; ++s) REQUIRE(f->pixel_at(s) == e->pixel_at(s));
  // An exact run against itself does not diverge.
  const CompareStats same = compare_traces(*e, *dda(in, Numeric::exact));
  CHECK_FALSE(same.first_decision_divergence);
  CHECK_FALSE(same.first_value_divergence);
  CHECK(same.pixel_mismatches == 0);
}

TEST_CASE("visualizer texture: a fill's colour attributes paint its pixels, other pixels keep the plot order's colour", "[visualizer][texture]") {
  // Red at every vertex, half green at one: each pixel's texel is its interpolated colour, 0xAABBGGRR.
  const auto m = dda(R"({"triangle":[[0,0],[12,1],[3,9]],"attrs":[[1,0,0],[1,0,0],[1,1,0]]})", Numeric::exact, "triangle-dda");
  MemoryTextures tex;
  PixelLayer layer(tex);
  REQUIRE(layer.prepare(m, WorldRect{-2, -2, 14, 11}, 10.0, m->last()));
  const CellWindow& w = layer.window();
  const auto& im = tex.image(layer.texture());
  const std::array<Vec2<Rational>, 3> t{Vec2<Rational>{0, 0}, {12, 1}, {3, 9}};
  std::size_t painted = 0;
  for (const PlotEvent& e : m->plots()) {
    const Rational g = oracle::linear_at(t, {0, 0, 1}, e.cell);  // the green channel's plane
    const std::uint32_t want = 0xff0000ffu | std::uint32_t(std::lround(255 * g.get_d())) << 8;
    const int u = int(e.cell.x - w.x0), v = w.h - 1 - int(e.cell.y - w.y0);
    INFO("cell " << e.cell.x << "," << e.cell.y);
    CHECK(im.px[std::size_t(v) * w.w + u] == want);
    ++painted;
  }
  CHECK(painted == oracle::triangle_samples(t).size());
  // Without attributes the same fill is painted by plot order.
  const auto plain = dda(R"({"triangle":[[0,0],[12,1],[3,9]]})", Numeric::exact, "triangle-dda");
  CHECK(plain->step_rgba(plain->plots()[0].step) == 0u);
}
#endif  // SW_HAVE_VISUALIZER
