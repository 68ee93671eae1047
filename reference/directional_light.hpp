#pragma once
#include "core/scene/scene.hpp"
#include "reference/reference_brdf.hpp"

namespace pbr::reference {

// The unit direction towards the light, against the way it travels.
dvec3 towardsLight(const DirectionalLight& light);

// Radiance towards V that the reference PBR model reflects from one directional light of illuminance E (lux):
// f(l, v) E n.l with l against the way the light travels; from behind the surface (n.l < 0), what a transmissive
// material lets through, f_T E |n.l| (transmissionLobe; 0 for the others).
dvec3 reflectedRadiance(const DirectionalLight& light, const dvec3& N, const dvec3& V, const ReferenceMaterial& m,
                        const BrdfForms& forms);

}  // namespace pbr::reference
