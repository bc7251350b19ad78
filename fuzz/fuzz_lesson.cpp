// libFuzzer harness for the lesson parser: front matter, the input it names, narration sections.
#include <cstddef>
#include <cstdint>
#include <string>
#include "input.hpp"
#include "lesson.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)sw::vis::parse_lesson(std::string(reinterpret_cast<const char*>(data), size), "fuzz.md");
  } catch (const sw::InputError&) {
  }
  return 0;
}
