// Mirrors pbr::ObjectBlock (gbuffer/object_block.hpp).
layout(std140, binding = OBJECT_UBO) uniform ObjectBlock {
  mat4 model;
  mat4 normalMatrix;
  vec4 baseColor;    // linear rgb factor, alpha factor
  vec4 material;     // roughness, metalness, normal scale, occlusion strength
  vec4 emissive;     // linear emitted radiance factor, alpha cutoff
  vec4 orientation;  // x: sign of det(model); y: the core maps reading TEXCOORD_1, a bit per texture unit; z: the
                     // extensions' maps reading it, a bit per map
  vec4 dielectric;   // KHR_materials_ior / _specular: the dielectric's F0 colour (rgb) and F90 (a)
  vec4 layers;       // KHR_materials_clearcoat's strength and roughness, KHR_materials_sheen's roughness, the
                     // coat's normal map scale
  vec4 sheenColor;   // KHR_materials_sheen's colour, linear; w unused
  vec4 transmission;  // KHR_materials_transmission's factor, KHR_materials_volume's thickness (object space) and
                      // attenuation distance (0: no absorption), the index of refraction
  vec4 attenuationColor;  // KHR_materials_volume's attenuation colour; w unused
  vec4 specularFactors;   // KHR_materials_specular's colour factor, and the F0 of the ior ((ior - 1) / (ior + 1))^2
  mat2x3 uvTransform[5];  // by material map texture unit: the rows of its 2x3 affine UV map
  mat2x3 extensionUvTransform[9];  // the extensions' maps', in the order of their units (17-25)
} object;
