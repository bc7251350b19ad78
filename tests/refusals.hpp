// An input the algorithm must refuse: one InputError line that names the problem (needle).
#pragma once
#include <catch2/catch.hpp>
#include <algorithm>
#include <filesystem>
#include <string>
#include "catalog.hpp"
#include "cli_harness.hpp"
#include "run.hpp"

namespace sw::testing {

inline void expect_refused(const Algorithm& alg, const std::string& text, const std::string& needle) {
  INFO(text);
  try {
    (void)alg.open(Json::parse(text), Numeric::exact);
    FAIL("accepted");
  } catch (const InputError& e) {
    const std::string what = e.what();
    CHECK(what.find('\n') == std::string::npos);
    CHECK(what.find(needle) != std::string::npos);
  }
}

// A command the CLI must refuse: exit 2, one line on stderr, and no output file left.
inline Ran expect_cli_refused(const std::string& args, const std::filesystem::path& out) {
  std::filesystem::remove(out);
  const Ran r = run_stepwise(args);
  INFO(args << ": " << r.err);
  CHECK(r.status == 2);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(!std::filesystem::exists(out));
  return r;
}

}  // namespace sw::testing
