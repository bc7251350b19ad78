// libFuzzer harness for `stepwise run`: the input parser, the validators, the work budget and the
// algorithms on what they accept. The data is "ALGORITHM NUMERIC\n" then one JSON input per line.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include "catalog.hpp"
#include "input.hpp"
#include "trace_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::istringstream in(text);
  std::string head;
  if (!std::getline(in, head)) return 0;
  const auto space = head.find(' ');
  if (space == std::string::npos) return 0;
  std::ostringstream out;
  try {
    const sw::Algorithm& alg = sw::find_algorithm(head.substr(0, space));
    const sw::Numeric n = sw::parse_numeric_for(alg, head.substr(space + 1));
    // A small budget keeps each run short under the sanitizers; the bound itself is what is tested.
    sw::run_batch(alg, n, in, out, sw::Budget{20'000, std::uint64_t{1} << 20});
  } catch (const sw::InputError&) {
  }
  return 0;
}
