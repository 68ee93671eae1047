#pragma once
#include <glm/vec3.hpp>

#include "core/scene/scene.hpp"
#include "reference/reference_brdf.hpp"

namespace pbr::reference {

// Where a point light stands from surface point P with unit normal N: the unit direction to it (N when the light
// sits on P), n.l, and the windowed attenuation at its distance, times a spot light's cone falloff.
struct LightIncidence {
  dvec3 L;
  double NoL;
  double attenuation;
};
LightIncidence incidence(const PointLight& light, const dvec3& P, const dvec3& N);

// Radiance towards V that the reference PBR model reflects from one point light, in the renderer's photometric
// units: f(l, v) I att n.l with intensity I = P / (4 pi) from the luminous power; from behind the surface
// (n.l < 0), what a transmissive material lets through, f_T I att |n.l| (transmissionLobe; 0 for the others).
dvec3 reflectedRadiance(const PointLight& light, const dvec3& P, const dvec3& N, const dvec3& V,
                        const ReferenceMaterial& m, const BrdfForms& forms);

}  // namespace pbr::reference
