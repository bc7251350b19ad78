// Reading an exact recorded step for the per-step expectations: every variable by name (integers
// exactly, numbers as rationals, vectors as name.x, name.y, name.z), and a check that fails for a variable no expectation looked at.
// Likewise every geometry item, and a check that fails for an item no expectation took.
#pragma once
#include <catch2/catch.hpp>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>
#include "core/probe.hpp"

namespace sw::testing {

// a / b in lowest terms (gmpxx leaves mpq_class(a, b) as given, and its arithmetic needs canonical
// operands).
inline Rational ratio(std::int64_t a, std::int64_t b) { return Rational(a) / Rational(b); }

struct StepValues {
  std::map<std::string, Rational> v;
  std::set<std::string> checked;
  // The value of `name`, marked as checked; the test fails if the step did not record it.
  const Rational& operator[](const std::string& name) {
    checked.insert(name);
    INFO("variable " << name);
    REQUIRE(v.count(name));
    return v.at(name);
  }
};

inline StepValues values_of(const Recorder<Rational>& t, std::size_t s) {
  StepValues out;
  for (std::uint32_t k = t.at(s).var_begin; k < t.at(s).var_end; ++k) {
    const VarRecord& var = t.var_at(k);
    auto at = [&](std::uint32_t c) { return var.is_int ? Rational(t.int_value(var.slot + c)) : t.num_value(var.slot + c); };
    const std::string name = var.name;
    switch (var.shape) {
      case VarShape::scalar: out.v[name] = at(0); break;
      case VarShape::vector:  // name.x, name.y, name.z
        for (std::uint32_t c = 0; c < var.count; ++c) out.v[name + "." + "xyz"[c]] = at(c);
        break;
      case VarShape::colour:  // name.r, name.g, name.b
        for (std::uint32_t c = 0; c < 3; ++c) out.v[name + "." + "rgb"[c]] = at(c);
        break;
      case VarShape::list:  // name.size, then name[0], name[1], ...
        out.v[name + ".size"] = Rational(var.count);
        for (std::uint32_t c = 0; c < var.count; ++c) out.v[name + "[" + std::to_string(c) + "]"] = at(c);
        break;
    }
  }
  return out;
}

// Every variable the step records must have been read by its expectation.
inline void require_all_checked(const StepValues& sv, std::size_t step) {
  for (const auto& [name, value] : sv.v) {
    INFO("step " << step << " records " << name << " with no expectation");
    CHECK(sv.checked.count(name));
  }
}

// One geometry item of an exact recorded step: its values (integer kinds exactly) and what else the
// step attached to it, with the mark an expectation sets when it has looked at the item.
struct GeoItem {
  GeoKind kind{};
  std::vector<Rational> values;
  std::string label;              // empty if none
  std::string life;               // empty: this step only; else the lifetime's name ("keep", ...)
  std::optional<Rational> value;  // a value a view colours the item by, if any
  bool checked = false;
};

struct StepGeometry {
  std::vector<GeoItem> items;
  // The first item of `kind` not taken yet (so several items of one kind are taken in recorded
  // order), marked as checked; the test fails if the step has none left.
  GeoItem& take(GeoKind kind) {
    for (GeoItem& g : items)
      if (g.kind == kind && !g.checked) {
        g.checked = true;
        return g;
      }
    FAIL("the step records no (further) " << geo_name(kind));
    throw std::logic_error("unreachable");
  }
};

inline StepGeometry geometry_of(const Recorder<Rational>& t, std::size_t s) {
  StepGeometry out;
  for (std::uint32_t g = t.at(s).geo_begin; g < t.at(s).geo_end; ++g) {
    const GeoRecord& r = t.geo_at(g);
    GeoItem item;
    item.kind = r.kind;
    for (std::uint32_t k = 0; k < r.count; ++k)
      item.values.push_back(geo_desc(r.kind).integer ? Rational(t.int_value(r.slot + k)) : t.num_value(r.slot + k));
    if (r.label) item.label = r.label;
    if (r.life != Life::step) item.life = std::string(life_name(r.life));
    if (r.value != GeoRecord::kNoValue) item.value = t.num_value(r.value);
    out.items.push_back(std::move(item));
  }
  return out;
}

// Every geometry item the step records must have been taken by its expectation.
inline void require_all_geometry_checked(const StepGeometry& g, std::size_t step) {
  for (const GeoItem& item : g.items) {
    INFO("step " << step << " records a " << geo_name(item.kind) << " with no expectation");
    CHECK(item.checked);
  }
}

// Calls check(s, line, values, geometry) for every step of listing L at scope 0 of an exact
// recording, requiring every variable and geometry item to be looked at; nested steps (a callee's
// listing) go to `nested`, and without one a nested step fails.
// Calls check(values, geometry) for step s, then requires every variable and item looked at.
template <class F> void check_step(const Recorder<Rational>& t, std::size_t s, F&& check) {
  StepValues sv = values_of(t, s);
  StepGeometry g = geometry_of(t, s);
  check(sv, g);
  require_all_checked(sv, s);
  require_all_geometry_checked(g, s);
}

template <class L, class F> void for_each_step(const Recorder<Rational>& t, F&& check, const std::function<void(std::size_t)>& nested = {}) {
  for (std::size_t s = 0; s < t.size(); ++s) {
    if (t.at(s).scope != 0) {
      INFO("nested step " << s);
      REQUIRE(nested);
      nested(s);
      continue;
    }
    const std::string_view line = L::lines[t.at(s).line - 1].name;
    INFO("step " << s << " line " << line);
    check_step(t, s, [&](StepValues& sv, StepGeometry& g) { check(s, line, sv, g); });
  }
}

// A 2D point or segment item's values.
inline void check_point(GeoItem& g, const Vec2<Rational>& p) { CHECK(g.values == std::vector<Rational>{p.x, p.y}); }
inline void check_segment(GeoItem& g, const Vec2<Rational>& a, const Vec2<Rational>& b) {
  CHECK(g.values == std::vector<Rational>{a.x, a.y, b.x, b.y});
}

}  // namespace sw::testing
