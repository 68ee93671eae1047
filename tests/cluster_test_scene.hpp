#pragma once
#include "core/scene.hpp"

namespace pbr::test {

// The culling tests' scene: a floor, a box and a sphere in depth, with a camera whose near plane some of the lights
// straddle. No lights.
Scene clusterScene();

}  // namespace pbr::test
