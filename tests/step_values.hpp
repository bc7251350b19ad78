// Reading an exact recorded step for the per-step expectations: every variable by name (integers
// exactly, numbers as rationals, vectors as name.x, name.y, name.z), and a check that fails for a variable no expectation looked at.
#pragma once
#include <catch2/catch.hpp>
#include <map>
#include <set>
#include <string>
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
    if (var.is_int) out.v[var.name] = Rational(t.int_value(var.slot));
    else if (var.count == 1) out.v[var.name] = t.num_value(var.slot);
    else  // a vector's components as name.x, name.y, name.z
      for (std::uint32_t c = 0; c < var.count; ++c) out.v[std::string(var.name) + "." + "xyz"[c]] = t.num_value(var.slot + c);
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

}  // namespace sw::testing
