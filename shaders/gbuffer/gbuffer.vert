#version 450 core
#include "../common/frame.glsl"
#include "object.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec2 vUv;

void main() {
  vNormal = mat3(object.normalMatrix) * inNormal;
  vUv = inUv;
  gl_Position = frame.viewProjection * (object.model * vec4(inPosition, 1.0));
}
