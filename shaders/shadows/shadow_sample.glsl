// Shadow-map visibility of a light at a surface point (pbr::ShadowMaps, core/gl/shadow_maps.hpp): 1 lit, 0 shadowed,
// between inside the filter's penumbra. The atlas holds reversed-Z depth (1 nearest the light); a comparison passes
// where the receiver is at least as near the light as the nearest caster.

// Mirrors pbr::GpuCascadeView, std430: one cascade of a directional light, an orthographic view.
struct CascadeView {
  vec4 row0, row1, row2;  // world -> the light's clip x, y and reversed-Z depth (w is 1)
  vec4 rect;              // atlas UV: offset xy, size zw; size 0: not rendered (nothing visible in it), lit
  vec4 params;            // x: texel world size
};

// Mirrors pbr::GpuShadowHeader, then the cascades.
layout(std430, binding = SHADOW_VIEW_SSBO) readonly buffer ShadowViews {
  uvec4 directionalShadow[MAX_DIRECTIONAL_LIGHTS];  // x: first cascade + 1 (0: none), y: cascades
  vec4 cascadeEnds;                                 // view depth where each cascade ends
  vec4 shadowAtlas;                                 // x: size in texels, y: its inverse
  CascadeView cascadeViews[];
};

// Per light-buffer index: 0 without shadows, else the first view + 1 (bits 0-25), log2 of its views' side (bits
// 26-29), SHADOW_CUBE set for six cube faces, SHADOW_FRAME_X for a spot view framed around x (pbr::lightShadowEntry).
layout(std430, binding = LIGHT_SHADOW_SSBO) readonly buffer LightShadows { uint lightShadow[]; };
#define SHADOW_CUBE 0x80000000u
#define SHADOW_FRAME_X 0x40000000u
// Per view: its atlas square, origin x | y << 14 | log2(side) << 28 in texels, 0 not rendered (pbr::packShadowSquare).
layout(std430, binding = SHADOW_SQUARE_SSBO) readonly buffer ShadowSquares { uint shadowSquares[]; };

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

#if !defined(SHADOW_FILTER_HARD) && !defined(SHADOW_FILTER_POISSON16)
// The 3x3 grid of bilinear comparisons a texel apart, from four gathers: the nine taps around texel coordinate t
// cover the 4x4 texels from floor(t - 0.5) - 1, each weighted (1 - f, 1, 1, f) along each axis (f the bilinear
// fraction), so gathering those 16 comparisons and weighting them gives the nine taps' sum in fewer fetches. The
// gathers' corners stay inside the view's square, as the taps' clamp keeps them.
float shadowGrid3x3(vec4 rect, vec2 uv, float depth) {
  vec2 t = uv * shadowAtlas.x - 0.5, base = floor(t), f = t - base;
  vec2 lo = rect.xy * shadowAtlas.x + 1.0, hi = (rect.xy + rect.zw) * shadowAtlas.x - 3.0;
  vec2 c = clamp(base, lo, hi) * shadowAtlas.y;  // the corner between the block's first two texels
  float d = 2.0 * shadowAtlas.y;
  // Gather order: (x0, y1), (x1, y1), (x1, y0), (x0, y0).
  vec4 g00 = textureGather(shadowAtlasMap, c, depth);
  vec4 g10 = textureGather(shadowAtlasMap, c + vec2(d, 0.0), depth);
  vec4 g01 = textureGather(shadowAtlasMap, c + vec2(0.0, d), depth);
  vec4 g11 = textureGather(shadowAtlasMap, c + vec2(d, d), depth);
  vec4 wx = vec4(1.0 - f.x, 1.0, 1.0, f.x), wy = vec4(1.0 - f.y, 1.0, 1.0, f.y);
  float sum = wy.x * (wx.x * g00.w + wx.y * g00.z + wx.z * g10.w + wx.w * g10.z) +
              wy.y * (wx.x * g00.x + wx.y * g00.y + wx.z * g10.x + wx.w * g10.y) +
              wy.z * (wx.x * g01.w + wx.y * g01.z + wx.z * g11.w + wx.w * g11.z) +
              wy.w * (wx.x * g01.x + wx.y * g01.y + wx.z * g11.x + wx.w * g11.y);
  return sum * (1.0 / 9.0);
}
#endif

// The filtered comparison of reversed-Z `depth` at atlas coordinate `uv` inside the square `rect` (atlas UV).
float shadowFilter(vec4 rect, vec2 uv, float depth) {
#if defined(SHADOW_FILTER_HARD)
  return shadowTap(rect, (floor(uv * shadowAtlas.x) + 0.5) * shadowAtlas.y, depth);
#elif defined(SHADOW_FILTER_POISSON16)
  float sum = 0.0;
  for (int i = 0; i < 16; ++i) sum += shadowTap(rect, uv + kPoisson16[i] * (1.5 * shadowAtlas.y), depth);
  return sum * (1.0 / 16.0);
#else
  return shadowGrid3x3(rect, uv, depth);
#endif
}

// The offset's length along the normal for a texel of world size `texel` at the point, whose unit normal is `normal`
// and unit direction to the light L. Normal-offset bias (Holbein 2011, "Normal Offset Shadows"): the point moves
// along its normal by what a plane tilted by theta from the light needs over the filter's reach, reach tan(theta) in
// depth, i.e. reach sin(theta) texels along the normal, plus half a texel for depth rounding.
float normalOffset(float texel, vec3 normal, vec3 L) {
  float NoL = clamp(dot(normal, L), 0.0, 1.0);
  return texel * (0.5 + SHADOW_REACH * sqrt(1.0 - NoL * NoL));
}

// Coordinates of d in the frame of cube face `face` (+X, -X, +Y, -Y, +Z, -Z): right, up and along the axis, as
// pbr::frameAround builds the faces' views (a test checks the two agree).
vec3 cubeFaceLocal(uint face, vec3 d) {
  switch (face) {
    case 0u: return vec3(d.z, d.y, d.x);
    case 1u: return vec3(-d.z, d.y, -d.x);
    case 2u: return vec3(-d.z, d.x, d.y);
    case 3u: return vec3(d.z, d.x, -d.y);
    case 4u: return vec3(-d.x, d.y, d.z);
    default: return vec3(d.x, d.y, -d.z);
  }
}

// The cube face of the major axis of d.
uint cubeFace(vec3 d) {
  vec3 a = abs(d);
  return a.x >= a.y && a.x >= a.z ? (d.x >= 0.0 ? 0u : 1u)
       : a.y >= a.z              ? (d.y >= 0.0 ? 2u : 3u)
                                 : (d.z >= 0.0 ? 4u : 5u);
}

// The visibility at view-frame coordinates f (right, up, along the axis; after the normal offset) of a perspective
// view with half-angle tangent t (border included) whose square is `square` (pbr::packShadowSquare) of side `side`,
// its near plane `near`: the projection pbr::perspectiveView renders with.
float perspectiveShadow(uint square, float side, float t, float near, vec3 f) {
  if (square == 0u || f.z <= 0.0) return 1.0;
  vec4 rect = vec4(float(square & 0x3fffu), float((square >> 14) & 0x3fffu), side, side) * shadowAtlas.y;
  return shadowFilter(rect, rect.xy + (f.xy / (t * f.z) * 0.5 + 0.5) * rect.zw, near / f.z);
}

// A point or spot light's visibility; `entry` is its lightShadow value (non-zero), `cone` its spot cone. Only the
// view's square is read from memory: the view follows from the light (pbr::perspectiveView), widened by
// SHADOW_BORDER_TEXELS with its near plane at SHADOW_NEAR_SCALE R.
// - A cube light: six 90-degree faces; the face is chosen after the normal offset, so the filter's reach stays
//   inside the face's border.
// - A spot light: one view over the outer cone, the axis and the cone's angle from the light's cone
//   (pbr::GpuSpotCone: the axis times the falloff's scale s, offset -cos(outer) s), the frame as pbr::frameAround
//   builds it around the helper axis the entry names.
// Both kinds end in the one filter call: each call site is another copy of the filter's code, and on llvmpipe a
// larger shader runs slower. A frame without spot lights (SPOT_LIGHTS 0) leaves the spot branch out, which llvmpipe
// would run under an empty lane mask for every lookup (`default` with 256 shadowed lights: 4 % of its lighting).
float lightShadowVisibility(uint entry, vec4 lightPositionRadius, vec4 cone, vec3 position, vec3 normal, vec3 L) {
  float side = float(1u << ((entry >> 26) & 15u));
  uint view = (entry & 0x3ffffffu) - 1u;
  vec3 d = position - lightPositionRadius.xyz, f;
  float t;
  if ((entry & SHADOW_CUBE) != 0u) {
    t = side / (side - 2.0 * SHADOW_BORDER_TEXELS);  // tan of the half angle with the border
    vec3 a = abs(d);
    float w = max(max(a.x, a.y), a.z);  // distance along the nearest face's axis
    d += normal * normalOffset(2.0 * t / side * w, normal, L);
    uint face = cubeFace(d);
    view += face;
    f = cubeFaceLocal(face, d);
  }
#if SPOT_LIGHTS
  else {
    float scale = length(cone.xyz);
    vec3 axis = cone.xyz / scale;
    float cosOuter = -cone.w / scale;
    t = sqrt(max(1.0 - cosOuter * cosOuter, 0.0)) / cosOuter * side / (side - 2.0 * SHADOW_BORDER_TEXELS);
    vec3 right = normalize(cross(axis, (entry & SHADOW_FRAME_X) != 0u ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
    vec3 up = cross(right, axis);
    d += normal * normalOffset(2.0 * t / side * dot(d, axis), normal, L);
    f = vec3(dot(d, right), dot(d, up), dot(d, axis));
  }
#endif
  float near = max(lightPositionRadius.w * SHADOW_NEAR_SCALE, 1e-4);
  return perspectiveShadow(shadowSquares[view], side, t, near, f);
}

// A directional light's visibility from the cascade that holds the pixel's view depth.
float directionalShadowVisibility(uint light, float viewDepth, vec3 position, vec3 normal, vec3 L) {
  uvec4 entry = directionalShadow[light];
  if (entry.x == 0u) return 1.0;
  // The cascades' ends rise, and those past the last are far away: the count of ends the depth passes, without a
  // loop, whose index llvmpipe would read the ends at with a load per pixel.
  uint cascade = min(uint(viewDepth > cascadeEnds.x) + uint(viewDepth > cascadeEnds.y) +
                         uint(viewDepth > cascadeEnds.z), entry.y - 1u);
  CascadeView v = cascadeViews[entry.x - 1u + cascade];
  if (v.rect.z <= 0.0) return 1.0;
  vec4 p = vec4(position + normal * normalOffset(v.params.x, normal, L), 1.0);
  vec3 ndc = vec3(dot(v.row0, p), dot(v.row1, p), dot(v.row2, p));
  return shadowFilter(v.rect, v.rect.xy + (ndc.xy * 0.5 + 0.5) * v.rect.zw, ndc.z);
}
