#pragma once
#include <glm/vec3.hpp>

#include "reference/reference_brdf.hpp"

namespace pbr::reference {

// The directional albedo of the reference BRDF, integral of f(l, v) n.l over the hemisphere, by deterministic
// stratified importance sampling: GGX visible normals for the specular lobe (Heitz 2018), cosine-weighted
// directions for the diffuse lobe. `samples` per axis of the stratified grid.
dvec3 directionalAlbedo(const ReferenceMaterial& m, double NoV, const BrdfForms& forms = {}, int samples = 64);

}  // namespace pbr::reference
