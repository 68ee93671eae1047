#pragma once
#include <cstddef>

#include <glm/mat2x4.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace pbr {

// std140 mirror of `ObjectBlock` in shaders/gbuffer/object.glsl: one per drawn object.
struct ObjectBlock {
  glm::mat4 model;
  glm::mat4 normalMatrix;  // inverse transpose of the model matrix (upper 3x3 used)
  glm::vec4 baseColor;     // linear rgb factor, alpha factor
  glm::vec4 material;      // roughness, metalness, normal scale, occlusion strength
  glm::vec4 emissive;      // linear emitted radiance factor, alpha cutoff
  glm::vec4 orientation;   // x: sign of det(model), which mirrors the tangent frame; y: the core maps reading
                           // TEXCOORD_1, a bit per texture unit (a small integer, exact in float); z: the
                           // extensions' maps reading it, a bit per map in extensionMaps' order; w unused
  glm::vec4 dielectric;    // the dielectric's F0 colour and F90 (dielectricSpecular, core/scene/scene.hpp)
  glm::vec4 layers;        // clearcoat strength and roughness (KHR_materials_clearcoat), sheen roughness, the
                           // coat's normal map scale
  glm::vec4 sheenColor;    // KHR_materials_sheen's colour, linear; w unused
  glm::vec4 transmission;  // KHR_materials_transmission's factor, KHR_materials_volume's thickness (object space)
                           // and attenuation distance (0: no absorption), the index of refraction
  glm::vec4 attenuationColor;  // KHR_materials_volume's attenuation colour; w unused
  glm::vec4 specularFactors;   // KHR_materials_specular's colour factor, and the F0 of the ior (its maps multiply)
  // Each material map's UV transform by texture unit: the GLSL mat2x3 whose two columns, each padded to a vec4 by
  // std140, are the rows of the 2x3 affine map (Material::*UvTransform transposed).
  glm::mat2x4 uvTransform[5];
  glm::mat2x4 extensionUvTransform[9];  // the extensions' maps', in extensionMaps' order
};
static_assert(offsetof(ObjectBlock, uvTransform) == 2 * 64 + 10 * 16, "ObjectBlock must match its std140 layout");
static_assert(offsetof(ObjectBlock, extensionUvTransform) == 2 * 64 + 10 * 16 + 5 * 32,
              "ObjectBlock must match its std140 layout");
static_assert(sizeof(ObjectBlock) == 2 * 64 + 10 * 16 + 14 * 32, "ObjectBlock must match its std140 layout");

}  // namespace pbr
