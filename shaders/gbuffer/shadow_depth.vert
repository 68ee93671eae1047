#version 450 core
// Shadow casters' depth from a light (pbr::GBufferPass::renderDepth): positions through the light's
// view-projection; with ALPHA_MASK the base colour's UVs (the second set with UV1, where the map reads it) and the
// vertex colours' alpha (VERTEX_COLORS) for the cut-out.
#include "object.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
#if ALPHA_MASK && UV1
layout(location = 5) in vec2 inUv1;
#endif
#if ALPHA_MASK && VERTEX_COLORS
layout(location = 4) in vec4 inColor;
#endif

layout(location = 0) uniform mat4 lightViewProjection;

#if ALPHA_MASK
layout(location = 1) out vec2 vUv;
#endif
#if ALPHA_MASK && VERTEX_COLORS
layout(location = 2) out float vAlpha;
#endif

void main() {
#if ALPHA_MASK && UV1
  vUv = ((uint(object.orientation.y) >> uint(BASE_COLOR_MAP_UNIT)) & 1u) != 0u ? inUv1 : inUv;
#elif ALPHA_MASK
  vUv = inUv;
#endif
#if ALPHA_MASK && VERTEX_COLORS
  vAlpha = inColor.a;
#endif
  gl_Position = lightViewProjection * (object.model * vec4(inPosition, 1.0));
}
