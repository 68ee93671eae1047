#version 450 core
// First pass of light assignment: every light's bounding sphere in view space, computed once per frame instead
// of once per tile and per cluster that tests it.
layout(local_size_x = 64) in;

#include "../common/frame.glsl"
#include "clusters.glsl"
#include "lights.glsl"

layout(std430, binding = CLUSTER_VIEW_LIGHTS_SSBO) writeonly buffer ViewLights { vec4 viewLights[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= clusterGrid.counts.x) return;
  vec4 pr = lights[i].positionRadius;
  viewLights[i] = vec4((frame.view * vec4(pr.xyz, 1.0)).xyz, pr.w);
}
