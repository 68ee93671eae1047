#pragma once
// What the mesh-reference tests share: their frame size, a scene of two spheres, and the reference's frame of a
// scene at that size.
#include <glm/vec2.hpp>

#include "core/scene/mesh.hpp"
#include "core/scene/scene.hpp"
#include "reference/reference_renderer.hpp"

namespace pbr::test {

inline const glm::ivec2 kReferenceSize{160, 90};

// A dielectric sphere of radius 1 and a metal one mirrored by a scale of -1 along x (its front faces must keep
// facing out), both tessellated as `mesh`, lit by two point lights and no ambient light: the GPU's ambient term
// is an approximation the reference does not share.
Scene sphereScene(const MeshData& mesh);

// The reference's frame of `scene` at kReferenceSize, ray-casting `geometry`.
reference::ReferenceFrame renderWith(const Scene& scene, reference::Geometry geometry);

}  // namespace pbr::test
