#pragma once
#include <glm/vec3.hpp>

#include "core/scene/scene.hpp"
#include "reference/reference_brdf.hpp"

namespace pbr::reference {

// The renderer's Blinn-Phong model in double: an LDR model whose light colours are intensities, without the PBR
// model's photometric units, and whose sum the caller clamps to [0, 1]. It reads the PBR material: diffuse colour
// (1 - metalness) baseColor, specular colour F0 (specularF0), and shininess n = 2 / alpha^2 - 2, which gives the
// lobe the width of GGX's at the same roughness.
enum class BlinnPhongLobe {
  Power,              // (n.h)^n
  SphericalGaussian,  // its fit e^(n (n.h - 1))
};

// The constant ambient term: 0.02 of the diffuse colour.
dvec3 blinnPhongAmbient(const ReferenceMaterial& m);

// One point light's contribution at P: (diffuse n.l + specular lobe(n.h)) colour attenuation; 0 where n.l <= 0.
dvec3 blinnPhongLight(const PointLight& light, const dvec3& P, const dvec3& N, const dvec3& V,
                      const ReferenceMaterial& m, BlinnPhongLobe lobe);

}  // namespace pbr::reference
