#include <doctest/doctest.h>

#include <regex>

#include "app/args.hpp"

using pbr::Args;
using pbr::OptionSpec;
using pbr::UsageError;

namespace {
const std::vector<OptionSpec> kSpecs = {{"--lights", "N", "", "4", ""}, {"--size", "WxH", "", "16x9", ""},
                                        {"--exposure", "X", "", "2.5", ""}, {"--flag", "", ""},
                                        {"--out", "F", ""}, {"--count", "N", "", "", "the scene's"}};
}

TEST_CASE("args: values, inline values and flags") {
  Args a(kSpecs, {"--lights", "64", "--size=320x180", "--flag"});
  CHECK(a.getInt("--lights", 0, 100) == 64);
  CHECK(a.getSize("--size") == glm::ivec2(320, 180));
  CHECK(a.has("--flag"));
  CHECK_FALSE(a.has("--exposure"));
  CHECK(a.getFloat("--exposure", 0.0f, 10.0f) == 2.5f);
  CHECK_FALSE(a.helpRequested());
  CHECK(Args(kSpecs, {"--help"}).helpRequested());
}

TEST_CASE("args: malformed input is a usage error") {
  CHECK_THROWS_AS(Args(kSpecs, {"--nope"}), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"stray"}), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--lights"}), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--flag=1"}), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--lights", "12x"}).getInt("--lights", 0, 100), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--lights", "101"}).getInt("--lights", 0, 100), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--size", "320"}).getSize("--size"), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--size", "0x10"}).getSize("--size"), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--size", "10x10x"}).getSize("--size"), UsageError);
  CHECK_THROWS_AS(Args(kSpecs, {"--exposure", "nan"}).getFloat("--exposure", 0, 10), UsageError);
}

TEST_CASE("args: a command that takes operands keeps them in order, options around them parsed as usual") {
  const Args a(kSpecs, {"a.json", "--lights", "8", "b.json", "--flag"}, true);
  CHECK(a.operands() == std::vector<std::string>{"a.json", "b.json"});
  CHECK(a.getInt("--lights", 0, 100) == 8);
  CHECK(a.has("--flag"));
  CHECK(Args(kSpecs, {"--lights", "8"}, true).operands().empty());
  CHECK_THROWS_WITH_AS(Args(kSpecs, {"a.json", "--nope"}, true), "unknown option '--nope'", UsageError);
  CHECK_THROWS_WITH_AS(Args(kSpecs, {"-x"}, true), "unknown option '-x'", UsageError);
}

TEST_CASE("args: an absent option reads as its table default, and the help prints that same default") {
  const Args a(kSpecs, {});
  CHECK(a.getInt("--lights", 0, 100) == 4);
  CHECK(a.getSize("--size") == glm::ivec2(16, 9));
  CHECK(a.get("--out").empty());
  // Reading an option without a value or default, or one the table lacks, is the command's mistake, not the user's.
  CHECK_THROWS_AS(a.getInt("--count", 0, 100), std::logic_error);
  CHECK_THROWS_AS(a.get("--missing"), std::logic_error);
  const std::string help = Args::helpText("t", "s", kSpecs);
  CHECK(std::regex_search(help, std::regex("\n  --lights N +\\(default 4\\)\n")));
  CHECK(std::regex_search(help, std::regex("\n  --count N +\\(default: the scene's\\)\n")));
  CHECK(std::regex_search(help, std::regex("\n  --out F *\n")));
}

TEST_CASE("args: defaults are written so that the parsers read them back") {
  CHECK(pbr::sizeText({1280, 720}) == "1280x720");
  CHECK(pbr::numberText(60.0) == "60");
  CHECK(pbr::numberText(0.25) == "0.25");
}
