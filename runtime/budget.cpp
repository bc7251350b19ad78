#include "budget.hpp"
#include <algorithm>

namespace sw {

// Exact numbers are at most 4096 characters each (input.cpp); depth is bounded by the JSON
// readers (kMaxJsonDepth).
std::size_t longest_string(const Json& j) {
  if (j.is_string()) return j.get_ref<const std::string&>().size();
  std::size_t m = 0;
  if (j.is_structured())
    for (const Json& v : j) m = std::max(m, longest_string(v));
  return m;
}

std::uint64_t step_weight(const Json& input, Numeric n) {
  // Rounded modes convert the input once; exact, filtered and reference modes compute on it.
  if (n != Numeric::exact && n != Numeric::filtered && n != Numeric::reference) return 1;
  return 1 + longest_string(input) / kDigitsPerWeight;
}

std::string budget_count_error(std::string& text) {
  constexpr std::uint64_t kMax = std::uint64_t{1} << 62;
  const bool digits = !text.empty() && text.size() <= 19 && text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits || std::stoull(text) > kMax) return "expected a whole number from 0 to " + std::to_string(kMax) + ", got '" + one_line(text, 40) + "'";
  return {};
}

std::uint64_t saturating_product(std::initializer_list<std::uint64_t> factors) {
  std::uint64_t p = 1;
  for (std::uint64_t f : factors) p = f != 0 && p > UINT64_MAX / f ? UINT64_MAX : p * f;
  return p;
}

}  // namespace sw
