#version 450 core
// Debug views of the cluster grid over the final frame: DEBUG_SLICES 0 colours each pixel by the number of
// lights in its cluster (heat map scaled to the frame's maximum), DEBUG_SLICES 1 by its depth slice. A legend
// bar with its end values is drawn at the bottom left.
layout(local_size_x = 8, local_size_y = 8) in;

#include "../common/frame.glsl"
#include "../common/digits.glsl"
#include "clusters.glsl"

layout(binding = SURFACE_DEPTH_UNIT) uniform sampler2D gDepth;
layout(rgba8, binding = 0) uniform image2D ldr;
layout(std430, binding = CLUSTER_SSBO) readonly buffer Headers { ClusterHeader headers[]; };
layout(std430, binding = CLUSTER_STATUS_SSBO) readonly buffer Status { uint demand, nonEmpty, maxPerCluster; } status;

// Black -> blue -> cyan -> green -> yellow -> red: ordered and readable in grey scale too.
vec3 heat(float t) {
  const vec3 stops[6] = vec3[6](vec3(0.0), vec3(0.0, 0.1, 0.9), vec3(0.0, 0.8, 0.9), vec3(0.1, 0.85, 0.1),
                                vec3(1.0, 0.9, 0.0), vec3(1.0, 0.05, 0.0));
  float x = clamp(t, 0.0, 1.0) * 5.0;
  int i = min(int(x), 4);
  return mix(stops[i], stops[i + 1], x - float(i));
}

vec3 sliceColor(uint slice) {
  float h = fract(float(slice) * 0.618034);
  vec3 rgb = clamp(abs(fract(h + vec3(0.0, 2.0, 1.0) / 3.0) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
  return mix(vec3(0.15), rgb, (slice & 1u) == 0u ? 0.9 : 0.6);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(frame.viewport.xy);
  if (any(greaterThanEqual(p, size))) return;
  uint maxCount = max(status.maxPerCluster, 1u);
  uint slices = clusterGrid.dims.z;
  vec3 base = imageLoad(ldr, p).rgb;
  vec3 shade = vec3(dot(base, vec3(0.2126, 0.7152, 0.0722)));
  vec3 color;
  float depth = texelFetch(gDepth, p, 0).r;
  if (depth <= 0.0) {
    color = shade * 0.3;
  } else {
    float zView = -frame.projParams.w / (depth + frame.projParams.z);
#if DEBUG_SLICES
    vec3 tint = sliceColor(depthSlice(-zView));
#else
    ClusterHeader h = headers[clusterIndex(uvec2(p), -zView)];
    vec3 tint = heat(float(h.count) / float(maxCount));
#endif
    color = mix(tint, tint * shade * 2.0, 0.35);
  }

  // Legend (image rows run bottom-up in GL; the font is drawn with y down).
  int scale = max(1, size.y / 180);
  ivec2 q = ivec2(p.x, size.y - 1 - p.y);
  ivec2 barOrigin = ivec2(8 * scale, size.y - 22 * scale);
  ivec2 barSize = ivec2(min(size.x / 3, 160 * scale), 6 * scale);
  ivec2 inBar = q - barOrigin;
  if (all(greaterThanEqual(inBar, ivec2(-scale))) && all(lessThan(inBar, barSize + scale)) ) {
    float t = clamp(float(inBar.x) / float(barSize.x - 1), 0.0, 1.0);
#if DEBUG_SLICES
    color = sliceColor(min(uint(t * float(slices)), slices - 1u));
#else
    color = heat(t);
#endif
    if (any(lessThan(inBar, ivec2(0))) || any(greaterThanEqual(inBar, barSize))) color = vec3(1.0);
  }
  ivec2 labelY = ivec2(0, barOrigin.y + barSize.y + 2 * scale);
#if DEBUG_SLICES
  uint hiLabel = slices - 1u;
#else
  uint hiLabel = status.maxPerCluster;
#endif
  ivec2 hiOrigin = ivec2(barOrigin.x + barSize.x - int(decimalDigits(hiLabel)) * 4 * scale, labelY.y);
  if (numberPixel(0u, ivec2(barOrigin.x, labelY.y), scale, q) || numberPixel(hiLabel, hiOrigin, scale, q)) {
    color = vec3(1.0);
  }
  imageStore(ldr, p, vec4(color, 1.0));
}
