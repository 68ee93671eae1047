#version 450 core
// Deferred lighting, one invocation per pixel. CLUSTERED 0 shades every light of the frame (the brute-force
// reference path); CLUSTERED 1 shades only the lights listed for the pixel's cluster, in the same ascending
// order, so both paths produce the same sums. LIGHTING_STATS counts light-pixel pairs per workgroup.
layout(local_size_x = 8, local_size_y = 8) in;

#include "surface.glsl"
#include "lights.glsl"
#if SHADING_MODEL_BLINN_PHONG
#include "model_blinn_phong.glsl"
#else
#include "model_pbr.glsl"
#endif
#if CLUSTERED
#include "clusters.glsl"
layout(std430, binding = CLUSTER_SSBO) readonly buffer Headers { ClusterHeader headers[]; };
layout(std430, binding = LIGHT_INDEX_SSBO) readonly buffer Indices { uint lightIndices[]; };
#endif
#if LIGHTING_STATS
// Per workgroup: light-pixel pairs evaluated, and pairs that contribute (attenuation > 0 and n.l > 0).
layout(std430, binding = LIGHTING_STATS_SSBO) buffer PairStats { uvec2 groupPairs[]; };
#endif

layout(rgba16f, binding = 0) uniform writeonly image2D hdrOut;

#if LIGHTING_STATS
bool contributes(Surface s, PointLight light) {
  float d;
  vec3 L = directionToLight(s.position, s.normal, light, d);
  return dot(s.normal, L) > 0.0 && distanceAttenuation(d, light.positionRadius.w) > 0.0;
}
#endif

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  Surface s;
  if (!readSurface(p, s)) {
    imageStore(hdrOut, p, vec4(0.0, 0.0, 0.0, 1.0));
    return;
  }
  vec3 color = shadeAmbient(s);
#if CLUSTERED
  ClusterHeader header = headers[clusterIndex(uvec2(p), s.viewDepth)];
  bool listed = listFits(header);
  uint count = listed ? header.count : lighting.counts.x;
#else
  uint count = lighting.counts.x;
#endif
#if LIGHTING_STATS
  uint contributing = 0u;
#endif
  for (uint i = 0u; i < count; ++i) {
#if CLUSTERED
    PointLight light = lights[listed ? lightIndices[header.offset + i] : i];
#else
    PointLight light = lights[i];
#endif
    color += shadeLight(s, light);
#if LIGHTING_STATS
    contributing += contributes(s, light) ? 1u : 0u;
#endif
  }
#if LIGHTING_STATS
  uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  atomicAdd(groupPairs[group].x, count);
  atomicAdd(groupPairs[group].y, contributing);
#endif
  // NaN compares false everywhere: keep only values known to be finite and non-negative.
  color = mix(vec3(0.0), color, greaterThanEqual(color, vec3(0.0)));
  imageStore(hdrOut, p, vec4(finishShading(color), 1.0));
}
