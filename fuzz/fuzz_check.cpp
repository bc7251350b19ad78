// libFuzzer harness for `stepwise check`: the trace reader, the replay and the divergence messages.
// The data is a trace; its first byte's low two bits choose the scope (everything, --decisions-only,
// --results-only).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include "trace_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  const auto scope = static_cast<sw::CheckScope>((data[0] & 3) % 3);
  const sw::CheckReport r = sw::check_trace(in, scope, sw::Budget{20'000, std::uint64_t{1} << 20});
  // Every outcome is one of the three statuses, with a message (the CLI prints it through one_line).
  if (r.status < 0 || r.status > 2 || r.message.empty()) __builtin_trap();
  return 0;
}
