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
  static double error(const Output&, const Output&) { return 0; }
};
// Names handles with the wrong signature: caught at handles.
struct WrongSignature : Fake {
  static constexpr std::array hooks{Hook::handles};
  static int handles() { return 0; }
};
struct Agreeing : Fake {
  static constexpr std::array hooks{Hook::error, Hook::canonical};
  static double error(const Output&, const Output&) { return 0; }
  static Json canonical(const Json& r) { return r; }
};

static_assert(hook_mismatch<Misspelt>() == std::size_t(Hook::canonical));
static_assert(hook_mismatch<Unnamed>() == std::size_t(Hook::error));
static_assert(hook_mismatch<WrongSignature>() == std::size_t(Hook::handles));
static_assert(hook_mismatch<Agreeing>() == kHookCount);
static_assert(hook_mismatch<Fake>() == kHookCount);

}  // namespace

TEST_CASE("spec hooks: a misspelt, unnamed or mistyped hook is found at compile time", "[catalog]") {
  CHECK(hook_mismatch<Misspelt>() == std::size_t(Hook::canonical));
  CHECK(hook_mismatch<Agreeing>() == kHookCount);
}
