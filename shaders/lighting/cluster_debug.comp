#version 450 core
// Debug views of the cluster grid over the final frame: DEBUG_SLICES 0 colours each pixel by the number of
// lights in its cluster (heat map scaled to the frame's maximum), DEBUG_SLICES 1 by its depth slice. The legend's
// bar ends at the frame's maximum, a number only the GPU knows, drawn here.
layout(local_size_x = 8, local_size_y = 8) in;

#include "../common/frame.glsl"
#include "clusters.glsl"
#include "heat.glsl"
#include "legend.glsl"

layout(binding = SURFACE_DEPTH_UNIT) uniform sampler2D gDepth;
layout(rgba8, binding = 0) uniform image2D ldr;
layout(std430, binding = CLUSTER_SSBO) readonly buffer Headers { ClusterHeader headers[]; };
layout(std430, binding = CLUSTER_STATUS_SSBO) readonly buffer Status { uint demand, nonEmpty, maxPerCluster; } status;

vec3 sliceColor(uint slice) {
  float h = fract(float(slice) * 0.618034);
  vec3 rgb = clamp(abs(fract(h + vec3(0.0, 2.0, 1.0) / 3.0) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
  return mix(vec3(0.15), rgb, (slice & 1u) == 0u ? 0.9 : 0.6);
}

vec3 legendRamp(float t) {
#if DEBUG_SLICES
  uint slices = clusterGrid.dims.z;
  return sliceColor(min(uint(t * float(slices)), slices - 1u));
#else
  return heat(t);
#endif
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(frame.viewport.xy);
  if (any(greaterThanEqual(p, size))) return;
  uint maxCount = max(status.maxPerCluster, 1u);
  vec3 base = imageLoad(ldr, p).rgb;
  vec3 shade = vec3(dot(base, vec3(0.2126, 0.7152, 0.0722)));
  vec3 color;
  float depth = texelFetch(gDepth, p, 0).r;
  if (depth <= 0.0) {
    color = shade * 0.3;
  } else {
    float zView = viewZAt(depth);
#if DEBUG_SLICES
    vec3 tint = sliceColor(depthSlice(-zView));
#else
    ClusterHeader h = headers[clusterIndex(uvec2(p), -zView)];
    vec3 tint = heat(float(h.count) / float(maxCount));
#endif
    color = mix(tint, tint * shade * 2.0, 0.35);
  }
  color = drawLegend(p, size, color);
#if !DEBUG_SLICES
  LegendLayout l = legendLayout(size);
  uint most = status.maxPerCluster;
  if (numberPixel(most, legendHighOrigin(l, decimalDigits(most)), l.scale, legendPoint(p, size))) color = vec3(1.0);
#endif
  imageStore(ldr, p, vec4(color, 1.0));
}
