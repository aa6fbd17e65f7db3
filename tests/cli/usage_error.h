// The cli tests' check of a usage error: the arguments are refused with exit 2, nothing on stdout and one line on
// stderr that names the bad input.
#pragma once

#include "run.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace clitest {

inline void checkUsageError(const std::vector<std::string>& args, const std::string& mention) {
  std::string joined;
  for (const auto& a : args) joined += a + " ";
  INFO(joined);
  const Result r = run(args);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find(mention) != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

} // namespace clitest
