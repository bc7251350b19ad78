// How `check` holds and compares a result (docs/trace-format.md). A result's lists of tuples (its
// pixels, cells or values: an array of arrays of numbers) are held flat, not as a Json array a
// tuple: a pixel costs 16 bytes instead of about 100, so that a result of millions of pixels costs
// about what its text does. Everything else is Json, compared by value_diff, and a list is
// compared as value_diff compares the array it was read from.
#pragma once
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include "catalog.hpp"
#include "check_values.hpp"

namespace sw::check_values {

// A list of tuples held flat: `arity` scalars a tuple, tuple after tuple, as 8-byte integers
// while each is one (pixels, cells), else as Json scalars.
struct Tuples {
  std::size_t arity = 0, count = 0;
  std::deque<std::int64_t> ints;
  std::vector<Json> items;  // in use once a scalar is not an integer: all count * arity of them
  bool integers = true;     // `ints` in use
  void push(Json v);
  // Scalar i as the JSON text reads it (a non-negative integer is an unsigned one).
  Json at(std::size_t i) const;
};

// A value as `check` holds it: its Json, but for the lists of tuples that are members of its
// result object, which are held in `lists` (the object then has no member of their names).
struct Held {
  Json json;
  std::map<std::string, Tuples, std::less<>> lists;
};

// A trace line, read as parse_json_text reads it (the same bounds and messages), the lists of
// tuples in its result ({"result": {"pixels": [[i, j], ...]}}) held in `lists`. A member that is
// an array but not of tuples of scalars of one length stays in the Json, and so does the rest.
Held read_trace_line(std::string_view text, std::string_view what);
// A result as the catalog writes it (Run::oracle_to, Run::run_to), its lists held.
Held read_result(std::string_view text);

// The result in the form the oracle states it, as Algorithm::canonical gives it: the held lists
// that are result_sets sorted, the rest through Algorithm::canonical (whole, its lists put back,
// where that does more than sort: Algorithm::reshapes_result).
Held canonical(const Algorithm& alg, Held result);

// What differs between the results `want` and `got`, as value_diff says it of their whole Json at
// "result": the first field in key order ("result.pixels[7][1]: expected 3, got 4").
std::optional<std::string> result_diff(const Held& want, const Held& got, const Tolerance& tol, bool exact);

}  // namespace sw::check_values
