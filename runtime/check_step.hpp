// `check`'s view of one step: a trace's step line against the exact replay's (docs/trace-format.md).
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include "catalog.hpp"
#include "check_values.hpp"
#include "flat_json.hpp"

namespace sw::check_values {

// "line 6 (plot: plot p)" for the replay's step `want`: where a student looks in the listing.
std::string line_label(const Json& want, const Listing& own);
// The step before a divergence, the last both agree on: where the replay was and the values it
// recorded there, which led to the divergent step. A trace value beyond the mode's tolerance of the
// replay's (--decisions-only does not compare numbers) is shown beside it.
std::string step_context(const std::string& want_text, const std::string& got_text, std::size_t index, const Listing& own, const Tolerance& tol);
// What differs between the replay's step and the trace's, naming the field; nothing if they agree.
std::optional<std::string> step_diff(const Json& want, const Json& got, const Tolerance& tol, const Listing& listing);
// The fast path (check_fast.cpp): true only where the trace's step `got` has a step line's shape,
// is step number `index` if it says, and step_diff finds nothing against the replay's `want`; false
// where those must be asked (they may still find it agrees).
bool step_agrees(const FlatJson& want, const FlatJson& got, std::size_t index, const Tolerance& tol, bool geometry);
// Throws InputError unless j is a step line; geometry false: "geo" may be left out (--decisions-only).
void require_step_shape(const Json& j, std::size_t lineno, bool geometry);

}  // namespace sw::check_values
