#version 450 core
#include "../common/frame.glsl"
#include "object.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;  // xyz along +u, w handedness
#if VERTEX_COLORS
layout(location = 4) in vec4 inColor;  // COLOR_0, linear RGBA
#endif
#if UV1
layout(location = 5) in vec2 inUv1;  // TEXCOORD_1
#endif

layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec2 vUv;
#if NORMAL_MAP || CLEARCOAT_NORMAL_MAP
layout(location = 2) out vec4 vTangent;
#endif
#if UV1
layout(location = 3) out vec2 vUv1;
#endif
#if VERTEX_COLORS
layout(location = 4) out vec4 vColor;
#endif

void main() {
  vNormal = mat3(object.normalMatrix) * inNormal;
  vUv = inUv;
#if UV1
  vUv1 = inUv1;
#endif
#if VERTEX_COLORS
  vColor = inColor;
#endif
#if NORMAL_MAP || CLEARCOAT_NORMAL_MAP
  // Tangents lie in the surface and move with it; a mirroring model matrix reverses the frame's handedness.
  vTangent = vec4(mat3(object.model) * inTangent.xyz, inTangent.w * object.orientation.x);
#endif
  gl_Position = frame.viewProjection * (object.model * vec4(inPosition, 1.0));
}
