// Real peers (POV-Ray, xvfb-run, Mesa's llvmpipe, Chromium) are required: a missing one fails the
// test, unless the build was configured with -DSW_REQUIRE_PEERS=OFF, which says so; then the test
// is skipped with a warning. scripts/setup.sh installs every peer, and CI builds with the default.
#pragma once
#include <catch2/catch.hpp>

#ifndef SW_REQUIRE_PEERS
#define SW_REQUIRE_PEERS 1
#endif

// In a TEST_CASE: returns from it (skipped) or fails when `available` is false.
#define SW_REQUIRE_PEER(available, what)                                                                         \
  do {                                                                                                           \
    if (!(available)) {                                                                                          \
      if (SW_REQUIRE_PEERS) FAIL(what << " is missing (scripts/setup.sh installs it; -DSW_REQUIRE_PEERS=OFF skips)"); \
      WARN(what << " is missing: skipped, as this build says (-DSW_REQUIRE_PEERS=OFF)");                         \
      return;                                                                                                    \
    }                                                                                                            \
  } while (false)
