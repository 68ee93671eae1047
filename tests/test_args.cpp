#include <doctest/doctest.h>

#include "app/args.hpp"

using pbr::Args;
using pbr::OptionSpec;
using pbr::UsageError;

namespace {
const std::vector<OptionSpec> kSpecs = {{"--lights", "N", ""}, {"--size", "WxH", ""}, {"--exposure", "X", ""},
                                        {"--flag", "", ""}};
}

TEST_CASE("args: values, inline values and flags") {
  Args a(kSpecs, {"--lights", "64", "--size=320x180", "--flag"});
  CHECK(a.getInt("--lights", 0, 0, 100) == 64);
  CHECK(a.getSize("--size", {1, 1}) == glm::ivec2(320, 180));
  CHECK(a.has("--flag"));
  CHECK(a.getFloat("--exposure", 2.5f, 0.0f, 10.0f) == 2.5f);
  CHECK_FALSE(a.helpRequested());
  CHECK(Args(kSpecs, {"--help"}).helpRequested());
}

TEST_CASE("args: malformed input is a usage error") {
  CHECK_THROWS_AS(Args(kSpecs, {"--nope"}), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"stray"}), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--lights"}), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--flag=1"}), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--lights", "12x"}).getInt("--lights", 0, 0, 100), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--lights", "101"}).getInt("--lights", 0, 0, 100), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--size", "320"}).getSize("--size", {1, 1}), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--size", "0x10"}).getSize("--size", {1, 1}), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--size", "10x10x"}).getSize("--size", {1, 1}), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--exposure", "nan"}).getFloat("--exposure", 1, 0, 10), UsageError);
}

TEST_CASE("args: a command that takes operands keeps them in order, options around them parsed as usual") {
  const Args a(kSpecs, {"a.json", "--lights", "8", "b.json", "--flag"}, true);
  CHECK(a.operands() == std::vector<std::string>{"a.json", "b.json"});
  CHECK(a.getInt("--lights", 0, 0, 100) == 8);
  CHECK(a.has("--flag"));
  CHECK(Args(kSpecs, {"--lights", "8"}, true).operands().empty());
  CHECK_THROWS_WITH_AS(Args(kSpecs, {"a.json", "--nope"}, true), "unknown option '--nope'", UsageError);
  CHECK_THROWS_WITH_AS(Args(kSpecs, {"-x"}, true), "unknown option '-x'", UsageError);
}
