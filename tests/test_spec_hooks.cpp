// The Spec concept holds a Spec's named hooks against its definitions: these fakes must be
// caught at compile time (a failure here fails the build), and every catalog Spec passes it
// (make_algorithm instantiates the same check).
#include <catch2/catch.hpp>
#include "spec.hpp"

using namespace sw;

namespace {

struct Fake {
  struct Input {};
  struct Output {};
};
// Names canonical but misspells it: caught at canonical.
struct Misspelt : Fake {
  static constexpr std::array hooks{Hook::canonical};
  static Json canonicl(const Json& r) { return r; }
};
// Defines error but does not name it: caught at error.
struct Unnamed : Fake {
  static constexpr std::string_view error_unit = "ulps";
  static double error(const Output&, const Output&) { return 0; }
};
// Names error but gives no unit for it (the bench's "max error (UNIT)"): caught at error.
struct ErrorWithoutUnit : Fake {
  static constexpr std::array hooks{Hook::error};
  static double error(const Output&, const Output&) { return 0; }
};
// Names handles with the wrong signature: caught at handles.
struct WrongSignature : Fake {
  static constexpr std::array hooks{Hook::handles};
  static int handles() { return 0; }
};
// Names result_keys but declares a string, not an array of keys: caught at result_keys.
struct KeysNotAnArray : Fake {
  static constexpr std::array hooks{Hook::result_keys};
  static constexpr int result_keys = 0;
};
// Defines a summary table but does not name it: caught at summary_table.
struct UnnamedSummary : Fake {
  static SummaryTable summary_table(const Input&, const TraceView&) { return {}; }
};
// A picture of the wrong type: caught at picture.
struct WrongPicture : Fake {
  static constexpr std::array hooks{Hook::picture};
  static int picture(const Input&, std::int64_t) { return 0; }
};
// Contract inputs as a single string, not an array of inputs: caught at contract_inputs.
struct InputsNotAnArray : Fake {
  static constexpr std::array hooks{Hook::contract_inputs};
  static constexpr std::string_view contract_inputs = "{}";
};
struct Agreeing : Fake {
  static constexpr std::array hooks{Hook::error, Hook::canonical};
  static constexpr std::string_view error_unit = "ulps";
  static double error(const Output&, const Output&) { return 0; }
  static Json canonical(const Json& r) { return r; }
};

static_assert(hook_mismatch<Misspelt>() == std::size_t(Hook::canonical));
static_assert(hook_mismatch<Unnamed>() == std::size_t(Hook::error));
static_assert(hook_mismatch<ErrorWithoutUnit>() == std::size_t(Hook::error));
static_assert(hook_mismatch<WrongSignature>() == std::size_t(Hook::handles));
static_assert(hook_mismatch<KeysNotAnArray>() == std::size_t(Hook::result_keys));
static_assert(hook_mismatch<UnnamedSummary>() == std::size_t(Hook::summary_table));
static_assert(hook_mismatch<WrongPicture>() == std::size_t(Hook::picture));
static_assert(hook_mismatch<InputsNotAnArray>() == std::size_t(Hook::contract_inputs));
static_assert(hook_mismatch<Agreeing>() == kHookCount);
static_assert(std::size_t(Hook::result_sets) + 1 == kHookCount, "kHookCount counts every Hook");
static_assert(hook_mismatch<Fake>() == kHookCount);

}  // namespace

TEST_CASE("spec hooks: a misspelt, unnamed or mistyped hook is found at compile time", "[catalog]") {
  CHECK(hook_mismatch<Misspelt>() == std::size_t(Hook::canonical));
  CHECK(hook_mismatch<Agreeing>() == kHookCount);
}
