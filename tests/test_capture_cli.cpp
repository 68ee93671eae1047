// pbr render --capture-frame: a frame the run never renders is refused before anything is made.
#include <doctest/doctest.h>

#include <string>

#include "tests/cli_util.hpp"

using namespace pbr::test;

TEST_CASE("capture: --capture-frame past the run's last frame, or below 1, exits 2 before rendering") {
  const TempDir dir;
  // The first frame, --warmup 1, --frames 2 and the capture frame: frames 1 to 5.
  const PbrRun past = runPbr(dir, {"render", "--warmup", "1", "--frames", "2", "--capture-frame", "6"});
  CHECK(past.exitCode == 2);
  CHECK(past.out.empty());
  CHECK(isOneLine(past.err));
  CHECK(past.err.find("--capture-frame 6 is past the run's last frame, 5 (the first frame, --warmup 1, --frames 2 "
                      "and the capture frame)") != std::string::npos);
  for (const char* frame : {"0", "-1", "two"}) {
    CAPTURE(frame);
    const PbrRun bad = runPbr(dir, {"render", "--capture-frame", frame});
    CHECK(bad.exitCode == 2);
    CHECK(bad.out.empty());
    CHECK(isOneLine(bad.err));
    CHECK(bad.err.find("--capture-frame expects an integer in [1, ") != std::string::npos);
  }
}
