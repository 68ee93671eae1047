#version 450 core
// The glTF metal-rough material (material.glsl) into the G-buffer; ALPHA_MASK discards below the alpha cutoff.
#include "../common/octahedral.glsl"
#include "material.glsl"

layout(location = 0) out vec4 outBaseColor;  // SRGB8_ALPHA8: encoded on write
layout(location = 1) out vec2 outNormal;     // RG16 octahedral
layout(location = 2) out vec4 outMaterial;   // RGBA8 roughness, metalness, occlusion, 1 unlit
layout(location = 3) out vec4 outEmission;   // the frame's RGBA16F radiance target, which lighting adds to
#if MATERIAL_SPECULAR
layout(location = 4) out vec4 outSpecular;   // RGBA16F dielectric F0 / 0.04 (1 exactly for the core material), F90
#endif
#if MATERIAL_CLEARCOAT
layout(location = 5) out vec4 outClearcoat;  // RGBA16 clearcoat strength, roughness, octahedral normal
#endif
#if MATERIAL_SHEEN
layout(location = 6) out vec4 outSheen;      // SRGB8_ALPHA8 sheen colour (encoded on write), roughness
#endif

void main() {
  MaterialSample m = sampleMaterial();
#if ALPHA_MASK
  // After every texture() call: implicit derivatives are undefined once neighbours may have discarded.
  if (m.base.a < object.emissive.w) discard;
#endif
  outBaseColor = vec4(m.base.rgb, 1.0);
#if MATERIAL_SPECULAR
  outSpecular = vec4(m.dielectric.rgb / 0.04, m.dielectric.a);
#endif
#if MATERIAL_CLEARCOAT
  outClearcoat = vec4(m.clearcoat, m.clearcoatRoughness, octEncode(m.clearcoatNormal));
#endif
#if MATERIAL_SHEEN
  outSheen = vec4(m.sheenColor, m.sheenRoughness);
#endif
  outNormal = octEncode(m.normal);
#if UNLIT
  // KHR_materials_unlit: the base colour is the radiance, written where emission goes; the flag keeps the
  // lighting pass from adding light to it (UNLIT_MATERIALS).
  outMaterial = vec4(m.roughness, m.metalness, m.occlusion, 1.0);
  outEmission = vec4(m.base.rgb, 0.0);
#else
  outMaterial = vec4(m.roughness, m.metalness, m.occlusion, 0.0);
  outEmission = vec4(m.emitted, 0.0);
#endif
}
