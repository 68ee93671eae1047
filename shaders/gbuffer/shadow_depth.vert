#version 450 core
// Shadow casters' depth from a light (pbr::GBufferPass::renderDepth): positions through the light's
// view-projection; with ALPHA_MASK the base colour's UVs for the cut-out.
#include "object.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;

layout(location = 0) uniform mat4 lightViewProjection;

#if ALPHA_MASK
layout(location = 1) out vec2 vUv;
#endif

void main() {
#if ALPHA_MASK
  vUv = inUv;
#endif
  gl_Position = lightViewProjection * (object.model * vec4(inPosition, 1.0));
}
