// Shadow-map visibility of a light at a surface point (pbr::ShadowMaps, core/shadow_maps.hpp): 1 lit, 0 shadowed,
// between inside the filter's penumbra. The atlas holds reversed-Z depth (1 nearest the light); a comparison passes
// where the receiver is at least as near the light as the nearest caster.

// Mirrors pbr::GpuShadowView, std430.
struct ShadowView {
  mat4 viewProjection;  // world -> the light's clip space
  vec4 rect;            // atlas UV: offset xy, size zw; size 0: not rendered (nothing visible in it), lit
  vec4 params;          // x: texel world size (per unit of w when perspective), y: 1 perspective
};

// Mirrors pbr::GpuShadowHeader, then the views.
layout(std430, binding = SHADOW_VIEW_SSBO) readonly buffer ShadowViews {
  uvec4 directionalShadow[MAX_DIRECTIONAL_LIGHTS];  // x: first view + 1 (0: none), y: cascades
  vec4 cascadeEnds;                                 // view depth where each cascade ends
  vec4 shadowAtlas;                                 // x: size in texels, y: its inverse
  ShadowView shadowViews[];
};
// Per light-buffer index: 0 without shadows, else the first view + 1, SHADOW_CUBE set for six cube faces.
layout(std430, binding = LIGHT_SHADOW_SSBO) readonly buffer LightShadows { uint lightShadow[]; };
#define SHADOW_CUBE 0x80000000u

layout(binding = SHADOW_ATLAS_UNIT) uniform sampler2DShadow shadowAtlasMap;

// The filter's reach in texels from the looked-up point: how far its taps' bilinear footprints, and the texel
// grid the caster was rasterized on, lie from it. The normal offset below covers a plane's depth change over it.
#if defined(SHADOW_FILTER_HARD)
#define SHADOW_REACH 0.5
#elif defined(SHADOW_FILTER_POISSON16)
#define SHADOW_REACH 2.5
const vec2 kPoisson16[16] = vec2[](
    vec2(-0.942, -0.399), vec2(0.946, -0.769), vec2(-0.094, -0.929), vec2(0.345, 0.294),
    vec2(-0.916, 0.458), vec2(-0.815, -0.879), vec2(-0.383, 0.277), vec2(0.975, 0.756),
    vec2(0.443, -0.975), vec2(0.537, -0.474), vec2(-0.265, -0.419), vec2(0.792, 0.191),
    vec2(-0.242, 0.997), vec2(-0.814, 0.914), vec2(0.200, 0.786), vec2(0.144, -0.141));
#else
#define SHADOW_REACH 2.0
#endif

// One bilinear comparison at `uv`, kept inside the view's square so that no tap reads a neighbour's texels.
float shadowTap(vec4 rect, vec2 uv, float depth) {
  vec2 lo = rect.xy + 0.5 * shadowAtlas.y, hi = rect.xy + rect.zw - 0.5 * shadowAtlas.y;
  return texture(shadowAtlasMap, vec3(clamp(uv, lo, hi), depth));
}

// Visibility from view `index` of the point `position` with unit normal `normal`, lit from unit direction L.
// Normal-offset bias (Holbein 2011, "Normal Offset Shadows"): the point moves along its normal by what a plane
// tilted by theta from the light needs over the filter's reach, reach tan(theta) in depth, i.e. reach sin(theta)
// texels along the normal, plus half a texel for depth rounding.
float shadowVisibility(uint index, vec3 position, vec3 normal, vec3 L) {
  ShadowView v = shadowViews[index];
  if (v.rect.z <= 0.0) return 1.0;
  vec4 clip = v.viewProjection * vec4(position, 1.0);
  // A perspective view's texel grows with w, the distance along its axis.
  float texel = v.params.x * (v.params.y > 0.0 ? clip.w : 1.0);
  float NoL = clamp(dot(normal, L), 0.0, 1.0);
  clip += v.viewProjection * vec4(normal * (texel * (0.5 + SHADOW_REACH * sqrt(1.0 - NoL * NoL))), 0.0);
  if (clip.w <= 0.0) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  vec2 uv = v.rect.xy + (ndc.xy * 0.5 + 0.5) * v.rect.zw;
  float depth = ndc.z;
#if defined(SHADOW_FILTER_HARD)
  return shadowTap(v.rect, (floor(uv * shadowAtlas.x) + 0.5) * shadowAtlas.y, depth);
#elif defined(SHADOW_FILTER_POISSON16)
  float sum = 0.0;
  for (int i = 0; i < 16; ++i) sum += shadowTap(v.rect, uv + kPoisson16[i] * (1.5 * shadowAtlas.y), depth);
  return sum * (1.0 / 16.0);
#else
  float sum = 0.0;
  for (int y = -1; y <= 1; ++y) {
    for (int x = -1; x <= 1; ++x) sum += shadowTap(v.rect, uv + vec2(x, y) * shadowAtlas.y, depth);
  }
  return sum * (1.0 / 9.0);
#endif
}

// A point or spot light's visibility; `entry` is its lightShadow value (non-zero).
float lightShadowVisibility(uint entry, vec3 lightPosition, vec3 position, vec3 normal, vec3 L) {
  uint first = (entry & ~SHADOW_CUBE) - 1u;
  if ((entry & SHADOW_CUBE) == 0u) return shadowVisibility(first, position, normal, L);
  // The cube face of the major axis from the light to the point: +X, -X, +Y, -Y, +Z, -Z.
  vec3 d = position - lightPosition, a = abs(d);
  uint face = a.x >= a.y && a.x >= a.z ? (d.x >= 0.0 ? 0u : 1u)
            : a.y >= a.z              ? (d.y >= 0.0 ? 2u : 3u)
                                      : (d.z >= 0.0 ? 4u : 5u);
  return shadowVisibility(first + face, position, normal, L);
}

// A directional light's visibility from the cascade that holds the pixel's view depth.
float directionalShadowVisibility(uint light, float viewDepth, vec3 position, vec3 normal, vec3 L) {
  uvec4 entry = directionalShadow[light];
  if (entry.x == 0u) return 1.0;
  uint cascade = 0u;
  while (cascade + 1u < entry.y && viewDepth > cascadeEnds[cascade]) ++cascade;
  return shadowVisibility(entry.x - 1u + cascade, position, normal, L);
}
