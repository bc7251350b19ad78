// The result keys the views read. A view reads a run's result only through read_result and one
// of these entries, and reads only keys the algorithm declares (its Spec's result_keys hook,
// Algorithm::result_keys), so that a result key renamed in a Spec cannot silently empty a view.
// tests/test_view_hooks.cpp holds every entry against the catalog: the algorithms an entry reads
// from declare its key where they must (or wherever their results have it), and every declared
// key is in the algorithm's results.
#pragma once
#include <algorithm>
#include <array>
#include <string_view>
#include "lessons/trace_model.hpp"

namespace sw::vis {

struct ResultRead {
  std::string_view key;
  std::string_view reader;               // who reads it, for messages
  bool (*reads_from)(const Algorithm&);  // the algorithms it is read from
  // Those algorithms must declare the key; otherwise it is read where declared (and must be
  // declared where their results have it).
  bool required;
};

namespace result_reads {

constexpr bool shows(const Algorithm& a, View v) { return std::find(a.views.begin(), a.views.end(), v) != a.views.end(); }

// The lobe view: the input's own eye, marked at the term's value.
inline constexpr ResultRead lobe_value{"value", "the lobe view's eye", [](const Algorithm& a) { return shows(a, View::lobe); },
                                       true};
// The scene view: the picked pixel's colour above the ray tree (a picture without a pick has none).
inline constexpr ResultRead scene_colour{"colour", "the scene view's pixel colour",
                                         [](const Algorithm& a) { return shows(a, View::scene) && !a.picture.pick.empty(); }, true};
// The compare strip of two algorithms of a compare group: each one's value.
inline constexpr ResultRead strip_value{"value", "the compare strip of two algorithms",
                                        [](const Algorithm& a) { return !a.compare_group.empty(); }, true};
// The compare strip of two number types without pixels to count: hit or miss, where there is one.
inline constexpr ResultRead strip_hit{"hit", "the compare strip's outcome",
                                      [](const Algorithm& a) { return !shows(a, View::plane2d); }, false};

inline constexpr std::array all{&lobe_value, &scene_colour, &strip_value, &strip_hit};

}  // namespace result_reads

// The run's result at r.key if its algorithm declares the key and the result has it; else nullptr.
inline const Json* read_result(const TraceModel& m, const ResultRead& r) {
  const Json& result = m.result();
  if (!m.algorithm().declares_result(r.key) || !result.is_object()) return nullptr;
  const auto it = result.find(std::string(r.key));
  return it == result.end() ? nullptr : &*it;
}

}  // namespace sw::vis
