// The time left in a bench sweep, as its progress lines print it: predictions from the configurations measured
// so far.
#include <doctest/doctest.h>

#include <vector>

#include "app/bench/bench_eta.hpp"

using pbr::BenchConfig;
using pbr::BenchSettings;
using pbr::SweepEta;

namespace {

// 100, 200 and 400 lights, clustered PBR, 1 warm-up + 1 timed + 1 statistics frame each.
BenchSettings settings(double maxSeconds) {
  BenchSettings s;
  s.lights = {100, 200, 400};
  s.culling = {pbr::Culling::Clustered};
  s.models = {pbr::ShadingModel::Pbr};
  s.warmup = 1;
  s.frames = 1;
  s.maxSeconds = maxSeconds;
  return s;
}

}  // namespace

TEST_CASE("bench eta: measured configurations at their rate, the rest in proportion to their light counts") {
  const BenchSettings s = settings(60.0);
  SweepEta eta(pbr::sweepConfigs(s), s);
  CHECK(eta.framesPerConfig() == 3);
  CHECK(eta.remainingSeconds({3, 3, 3}) == 0.0);  // nothing to predict from yet
  // 0.1 s a frame at 100 lights, 2 frames left; then 3 frames at 200 (0.2 s each) and 3 at 400 (0.4 s each).
  eta.measured(0, 0.1);
  CHECK(eta.remainingSeconds({2, 3, 3}) == doctest::Approx(0.2 + 0.6 + 1.2));
  // A measured rate replaces the prediction, a configuration with no frames left costs nothing, and 200 lights
  // now lie on the line through 100 and 400: 0.1 + 100 x 0.4 / 300 s a frame.
  eta.measured(2, 0.5);
  CHECK(eta.remainingSeconds({0, 3, 1}) == doctest::Approx(3 * (0.1 + 0.4 / 3) + 0.5));
}

TEST_CASE("bench eta: two measured light counts give a line, whose fixed part proportion would miss") {
  const BenchSettings s = settings(60.0);
  SweepEta eta(pbr::sweepConfigs(s), s);
  // 0.5 s + 0.001 s per light a frame.
  eta.measured(0, 0.6);
  eta.measured(1, 0.7);
  CHECK(eta.remainingSeconds({0, 0, 3}) == doctest::Approx(3 * 0.9));
  CHECK(eta.remainingSeconds({0, 1, 3}) == doctest::Approx(0.7 + 3 * 0.9));
}

TEST_CASE("bench eta: a configuration predicted over --max-seconds costs the one frame before it is skipped") {
  const BenchSettings s = settings(1.0);
  SweepEta eta(pbr::sweepConfigs(s), s);
  eta.measured(0, 0.1);
  // 400 lights: 0.4 s a frame, 1.2 s in all, over 1 s: skipped after its first frame. 200 lights: 0.6 s.
  CHECK(eta.remainingSeconds({0, 3, 3}) == doctest::Approx(0.6 + 0.4));
}

TEST_CASE("bench eta: a skipped configuration has no frames left, yet its one frame predicts the others") {
  const BenchSettings s = settings(1.0);
  SweepEta eta(pbr::sweepConfigs(s), s);
  eta.measured(0, 1.0);  // its first frame took 1 s: 3 s estimated, skipped
  // 2 s and 4 s a frame predicted: both over --max-seconds, one frame each.
  CHECK(eta.remainingSeconds({0, 3, 3}) == doctest::Approx(2.0 + 4.0));
}

TEST_CASE("bench eta: durations print in seconds, minutes or hours") {
  CHECK(pbr::formatDuration(0.2) == "0 s");
  CHECK(pbr::formatDuration(42.4) == "42 s");
  CHECK(pbr::formatDuration(59.6) == "1 min 00 s");
  CHECK(pbr::formatDuration(185.0) == "3 min 05 s");
  CHECK(pbr::formatDuration(7620.0) == "2 h 07 min");
}
