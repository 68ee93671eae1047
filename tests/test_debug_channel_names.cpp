// The debug channels' names as the command line meets them: every name parses back to its channel, `render --help`
// lists them all, and a channel `pbr render` cannot show is refused with one line before any context is made.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "debug/debug_channel.hpp"
#include "tests/cli_util.hpp"

using pbr::test::isOneLine;
using pbr::test::runPbr;
using pbr::test::TempDir;

TEST_CASE("debug channels: twelve names, each parsed back to its channel, unknown ones refused naming the valid ones") {
  const std::string names = "basecolor, normal, roughness, metalness, occlusion, emission, depth, clusters, slices, "
                            "efficiency, shadows, transparency";
  CHECK(pbr::debugChannelNames(", ") == names);
  for (const pbr::DebugChannel channel : pbr::kDebugChannels) {
    CHECK((pbr::parseDebugChannel(pbr::toString(channel)) == channel));
  }
  CHECK_THROWS_WITH_AS(pbr::parseDebugChannel("baseColor"),
                       ("unknown debug channel 'baseColor' (expected " + names + ")").c_str(), std::invalid_argument);
  CHECK(pbr::needsClusterGrid(pbr::DebugChannel::Clusters));
  CHECK(pbr::needsClusterGrid(pbr::DebugChannel::Slices));
  CHECK_FALSE(pbr::needsClusterGrid(pbr::DebugChannel::Efficiency));
}

TEST_CASE("debug channels: render --help lists every channel, an unknown one exits 2 before a context") {
  const TempDir dir;
  const pbr::test::PbrRun help = runPbr(dir, {"render", "--help"});
  CHECK(help.exitCode == 0);
  CHECK(help.out.find(pbr::debugChannelNames()) != std::string::npos);

  // Refused at the arguments: the CPU tests have no EGL driver, so any attempt at a context would fail otherwise.
  const pbr::test::PbrRun unknown = runPbr(dir, {"render", "--debug", "albedo", "--size", "32x18"});
  CHECK(unknown.exitCode == 2);
  CHECK(unknown.out.empty());
  CHECK(isOneLine(unknown.err));
  CHECK(unknown.err.find("unknown debug channel 'albedo'") != std::string::npos);
  CHECK(unknown.err.find(pbr::debugChannelNames(", ")) != std::string::npos);

  // The cluster views need the grid of clustered culling; the efficiency view is measured with either.
  const pbr::test::PbrRun slices = runPbr(dir, {"render", "--debug", "slices", "--culling", "none"});
  CHECK(slices.exitCode == 2);
  CHECK(slices.out.empty());
  CHECK(isOneLine(slices.err));
  CHECK(slices.err.find("--debug slices needs --culling clustered") != std::string::npos);
}
