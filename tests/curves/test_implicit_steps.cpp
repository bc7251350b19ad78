// implicit-curve: every recorded value of every exact step against a closed form.
#include <catch2/catch.hpp>
#include <optional>
#include <set>
#include "implicit_support.hpp"

using namespace sw;
using namespace sw::testing::implicit;
using sw::testing::ratio;
using sw::testing::StepValues;
using sw::testing::require_all_checked;
using sw::testing::values_of;

TEST_CASE("implicit-curve: every value an exact step records matches its closed form", "[curves][replay]") {
  std::vector<std::pair<std::string, Case>> cases;
  for (const auto& [name, in] : corpus()) cases.push_back({name, case_of(in)});
  cases.push_back({"the example", case_of(Json::parse(find_algorithm("implicit-curve").example))});
  std::mt19937_64 rng(19);
  for (int i = 0; i < 40; ++i) cases.push_back({"random " + std::to_string(i), random_case(rng, i)});
  REQUIRE(cases.size() >= 48);
  const Listing L = curves::ImplicitCurve::listing();
  std::set<std::string_view> lines_seen;
  for (const auto& [name, k] : cases) {
    Recorder<Rational> t;
    std::vector<Pixel> out;
    const curves::WalkEnd end = curves::implicit_curve<Rational>(poly<Rational>(k), out, t);
    // The walk's state, followed from the steps' own records and the closed forms.
    Pixel p = k.start;
    std::int64_t moves = 0;
    int major = 0, sa = 0, sb = 0, gb = 0;
    Rational PM;
    Pixel next = p;
    std::optional<std::string> stop;
    bool table_done = false;
    std::set<Pixel> plotted;
    std::vector<Pixel> plot_order;
    for (std::size_t s = 0; s < t.size(); ++s) {
      const std::string_view line = L.lines[t.at(s).line - 1].name;
      lines_seen.insert(line);
      INFO(name << " step " << s << " line " << line);
      StepValues sv = values_of(t, s);
      struct Item {
        GeoKind first;  // the kind
        std::vector<Rational> second;  // its values
        std::string label;
        std::optional<Rational> value;
        Life life;
      };
      std::vector<Item> geo;
      for (std::uint32_t g = t.at(s).geo_begin; g < t.at(s).geo_end; ++g) {
        const GeoRecord& r = t.geo_at(g);
        std::vector<Rational> vals;
        for (std::uint32_t q = 0; q < r.count; ++q)
          vals.push_back(geo_desc(r.kind).integer ? Rational(t.int_value(r.slot + q)) : t.num_value(r.slot + q));
        geo.push_back({r.kind, vals, r.label ? r.label : "", r.value == GeoRecord::kNoValue ? std::nullopt : std::optional(t.num_value(r.value)), r.life});
        if (line != "decide") CHECK(geo.back().label.empty());  // only the decision's midpoint is labelled and valued
        if (line != "decide") CHECK_FALSE(geo.back().value);
        CHECK(geo.back().life == Life::step);
      }
      // 2M = 2p + 2 s_a e_a + s_b e_b.
      const std::int64_t mu = 2 * p.x + (major == 0 ? 2 * sa : sb), mv = 2 * p.y + (major == 1 ? 2 * sa : sb);
      if (line == "start") {
        CHECK(s == 0);
        CHECK(sv["degree"] == degree_of(k.c));
        CHECK(sv["x"] == k.start.x);
        CHECK(sv["y"] == k.start.y);
        CHECK(geo.empty());
      } else if (line == "plot") {
        REQUIRE(geo.size() == 1);
        CHECK(geo[0].first == GeoKind::pixel);
        const Pixel at{geo[0].second[0].get_num().get_si(), geo[0].second[1].get_num().get_si()};
        CHECK(at == (moves == 0 ? k.start : next));
        CHECK(plotted.insert(at).second);  // each pixel once
        plot_order.push_back(at);
        p = at;
      } else if (line == "grad") {
        CHECK(sv["x"] == p.x);
        CHECK(sv["y"] == p.y);
        const Rational gx = P(k.c, p.x, p.y, 1, 0), gy = P(k.c, p.x, p.y, 0, 1);
        CHECK(sv["gx"] == gx);
        CHECK(sv["gy"] == gy);
        CHECK(moves < k.max_steps);
        if (gx == 0 && gy == 0) stop = "singular";
        // The axes as the documentation states them, for the steps that follow.
        const Rational tx = -gy, ty = gx;
        major = abs(tx) > abs(ty) || (abs(tx) == abs(ty) && sgn(tx) * sgn(ty) < 0) ? 0 : 1;
        sa = sgn(major == 0 ? tx : ty);
        gb = sgn(major == 0 ? gy : gx);
        sb = sgn(major == 0 ? ty : tx) != 0 ? sgn(major == 0 ? ty : tx) : -gb;
        CHECK(geo.empty());
      } else if (line == "axes") {
        CHECK(!stop);
        CHECK(sv["major"] == major);
        CHECK(sv["sa"] == sa);
        CHECK(sv["sb"] == sb);
        CHECK(sa != 0);
        CHECK(sb != 0);
        CHECK(geo.empty());
      } else if (line == "table" || line == "probe") {
        CHECK(table_done == (line == "probe"));  // the table is made once, at the first midpoint
        table_done = true;
        CHECK(sv["u"] == mu);
        CHECK(sv["v"] == mv);
        PM = P(k.c, ratio(mu, 2), ratio(mv, 2));
        if (line == "table") {
          for (int m = 0; m < 4; ++m)
            for (int n = 0; m + n < 4; ++n) CHECK(sv["Q" + std::to_string(m) + std::to_string(n)] == diff(k.c, mu, mv, m, n));
          CHECK(diff(k.c, mu, mv, 0, 0) == PM);
        } else {
          CHECK(sv["PM"] == PM);
        }
        REQUIRE(geo.size() == 1);
        CHECK(geo[0].first == GeoKind::point2);
        CHECK(geo[0].second == std::vector<Rational>{ratio(mu, 2), ratio(mv, 2)});
      } else if (line == "decide") {
        CHECK(sv["PM"] == PM);
        const bool diagonal = sgn(PM) * sb * gb < 0;
        CHECK(sv["diagonal"] == diagonal);
        next = p;
        (major == 0 ? next.x : next.y) += sa;
        if (diagonal) (major == 0 ? next.y : next.x) += sb;
        // The midpoint, labelled and valued by P there: its sign is the decision.
        REQUIRE(geo.size() == 1);
        CHECK(geo[0].first == GeoKind::point2);
        CHECK(geo[0].second == std::vector<Rational>{ratio(mu, 2), ratio(mv, 2)});
        CHECK(geo[0].label == "P(M)");
        CHECK(geo[0].value == std::optional<Rational>(PM));
      } else if (line == "move") {
        ++moves;
        CHECK(sv["x"] == next.x);
        CHECK(sv["y"] == next.y);
        CHECK(sv["k"] == moves);
        if (next == k.start) stop = "closed";
        else if (plotted.count(next)) stop = "revisit";
        CHECK(geo.empty());
      } else if (line == "done") {
        CHECK(s + 1 == t.size());
        if (!stop) {
          CHECK(moves == k.max_steps);
          stop = "max_steps";
        }
        CHECK(curves::kWalkStopNames[sv["stopped"].get_num().get_si()] == *stop);
        CHECK(sv["steps"] == moves);
        CHECK(geo.empty());
      } else {
        FAIL("no expectation for line " << line);
      }
      require_all_checked(sv, s);
    }
    CHECK(plot_order == out);
    CHECK(end.steps == moves);
    CHECK((stop && curves::kWalkStopNames[static_cast<std::size_t>(end.stopped)] == *stop));
  }
  CHECK(lines_seen.size() == L.lines.size());
}
