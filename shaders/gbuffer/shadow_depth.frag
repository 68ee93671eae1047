#version 450 core
// Depth only; an alpha-masked material casts its cut-out, discarding where the G-buffer pass does.
#include "object.glsl"

#if ALPHA_MASK
layout(location = 1) in vec2 vUv;
#if VERTEX_COLORS
layout(location = 2) in float vAlpha;
#endif
#if BASE_COLOR_MAP
layout(binding = BASE_COLOR_MAP_UNIT) uniform sampler2D baseColorMap;
#endif
#endif

void main() {
#if ALPHA_MASK
  float alpha = object.baseColor.a;
#if VERTEX_COLORS
  alpha *= vAlpha;
#endif
#if BASE_COLOR_MAP
  alpha *= texture(baseColorMap, vec3(vUv, 1.0) * object.uvTransform[BASE_COLOR_MAP_UNIT]).a;
#endif
  if (alpha < object.emissive.w) discard;
#endif
}
