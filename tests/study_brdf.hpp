#pragma once
// The PBR model of the Blinn-Phong-vs-PBR study, written out in double precision from its equations, so that
// the renderer's `study` variant (GLSL) and the reference's study forms are both checked against one evaluation
// that shares no code with either.
#include <glm/vec3.hpp>

namespace pbr::test {

// f_d + f_s for unit N, V, L with n.v > 0 and n.l > 0; perceptual roughness, alpha = roughness^2 unclamped.
glm::dvec3 studyBrdf(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L, const glm::dvec3& baseColor,
                     double roughness, double metalness);

}  // namespace pbr::test
