// Mirrors pbr::ObjectBlock (gbuffer/object_block.hpp).
layout(std140, binding = OBJECT_UBO) uniform ObjectBlock {
  mat4 model;
  mat4 normalMatrix;
  vec4 baseColor;    // linear rgb factor, alpha factor
  vec4 material;     // roughness, metalness, normal scale, occlusion strength
  vec4 emissive;     // linear emitted radiance factor, alpha cutoff
  vec4 orientation;  // x: sign of det(model); y: the maps reading TEXCOORD_1, a bit per texture unit
  vec4 dielectric;   // KHR_materials_ior / _specular: the dielectric's F0 colour (rgb) and F90 (a)
  vec4 layers;       // KHR_materials_clearcoat's strength and roughness, KHR_materials_sheen's roughness; w unused
  vec4 sheenColor;   // KHR_materials_sheen's colour, linear; w unused
  vec4 transmission;  // KHR_materials_transmission's factor, KHR_materials_volume's thickness (object space) and
                      // attenuation distance (0: no absorption), the index of refraction
  vec4 attenuationColor;  // KHR_materials_volume's attenuation colour; w unused
  mat2x3 uvTransform[5];  // by material map texture unit: the rows of its 2x3 affine UV map
} object;
