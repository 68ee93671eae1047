#pragma once
#include <cstddef>

#include <glm/vec4.hpp>

#include "core/scene/caster_plane.hpp"

namespace pbr {

// std140 mirror of shaders/lighting/cluster_occupancy.glsl's CasterPlanes block: the frame's caster planes in view
// space (xyz the unit normal, w the offset) and each one's thickness (x), tested by the occupancy pass; how many
// are set is its CASTER_PLANES define.
struct CasterPlanesBlock {
  glm::vec4 planes[kMaxCasterPlanes];
  glm::vec4 tolerances[kMaxCasterPlanes];
};
static_assert(sizeof(CasterPlanesBlock) == 2 * kMaxCasterPlanes * 16, "std140: two vec4 arrays");

}  // namespace pbr
