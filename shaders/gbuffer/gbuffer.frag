#version 450 core
#include "../common/octahedral.glsl"
#include "object.glsl"

layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec2 vUv;

layout(location = 0) out vec4 outBaseColor;  // SRGB8_ALPHA8: encoded on write
layout(location = 1) out vec2 outNormal;     // RG16 octahedral
layout(location = 2) out vec2 outMaterial;   // RG8 roughness, metalness

void main() {
  outBaseColor = vec4(object.baseColor.rgb, 1.0);
  outNormal = octEncode(normalize(vNormal));
  outMaterial = object.material.xy;
}
