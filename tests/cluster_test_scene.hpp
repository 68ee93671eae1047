#pragma once
#include <cstdint>

#include "core/scene/builtin_scenes.hpp"
#include "core/scene/scene.hpp"

namespace pbr::test {

// The culling tests' scene: a floor, a box and a sphere in depth, with a camera whose near plane some of the lights
// straddle. No lights.
Scene clusterScene();

// clusterScene with `lights` seeded random lights in a slab through it, `spotShare` of them spot lights, of radii
// between `radiusMin` and `radiusMax`, their power shared out so that sums of up to a million stay within half floats.
Scene litClusterScene(int lights, uint64_t seed, float radiusMin, float radiusMax, float spotShare);

}  // namespace pbr::test
