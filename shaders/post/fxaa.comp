#version 450 core
// Anti-aliasing of the display image (sRGB-encoded RGBA8, after tone mapping), after Lottes 2011, "FXAA 3.11"
// (quality preset 12): find pixels on a luma edge, estimate the edge's direction and how far along it the pixel
// lies from the edge's ends, and resample the image across the edge by the matching sub-pixel amount. Works on
// encoded values, where the eye judges contrast; HDR captures are never filtered.
// Two builds: FXAA_EDGE_PIXELS 0, an invocation per pixel, copies the pixels off any edge and lists the others;
// FXAA_EDGE_PIXELS 1, dispatched indirectly over that list, filters them. A SIMD group of pixels runs the edge
// code once any of its pixels needs it (on llvmpipe, and on a GPU), so the list packs the edges together: at
// 1280x720 llvmpipe took 21 ms for the pass in one build, most of it the edge code run for pixels off edges.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D displayIn;  // bilinear, clamped to the edge
layout(rgba8, binding = 0) uniform writeonly image2D displayOut;

// Mirrors pbr::FxaaEdgesHeader (post/fxaa_pass.hpp): the second build's indirect dispatch, then the edge pixels,
// x | y << 16 each.
layout(std430, binding = FXAA_EDGES_SSBO) buffer Edges {
  uvec4 edgeDispatch;  // workgroups x, y, z; w: edge pixels listed
  uint edgePixels[];
};

// Edges fainter than this share of the local maximum luma, or than the absolute floor, are left alone; the
// sub-pixel term's strength (0: off, 1: softest). The preset's values.
const float kEdgeThreshold = 0.166, kEdgeThresholdMin = 0.0833, kSubpixel = 0.75;
// Steps of the search along the edge, in pixels (preset 12).
const int kSearchSteps = 5;
const float kStep[kSearchSteps] = float[](1.0, 1.5, 2.0, 4.0, 12.0);

vec2 gTexel;
ivec2 gPixel, gLast;

float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }
// Filtered reads only where the search needs them, between pixels: llvmpipe filters slowly.
float lumaAt(vec2 uv) { return luma(textureLod(displayIn, uv, 0.0).rgb); }
float lumaOffset(ivec2 offset) { return luma(texelFetch(displayIn, clamp(gPixel + offset, ivec2(0), gLast), 0).rgb); }

// Whether the last pixel fxaaPixel saw lies on an edge, and its colour (the first build's).
bool gOnEdge;
vec4 gCentre;

// FXAA at pixel p of an image of `size`: the first build finds whether it lies on an edge (gOnEdge, gCentre); the
// second filters it.
void fxaaPixel(ivec2 p, ivec2 size) {
  gTexel = 1.0 / vec2(size);
  gPixel = p;
  gLast = size - 1;
  vec2 uv = (vec2(p) + 0.5) * gTexel;
  vec4 centre = texelFetch(displayIn, p, 0);
  float m = luma(centre.rgb);
  float n = lumaOffset(ivec2(0, 1)), s = lumaOffset(ivec2(0, -1));
  float e = lumaOffset(ivec2(1, 0)), w = lumaOffset(ivec2(-1, 0));
  float maxLuma = max(m, max(max(n, s), max(e, w))), minLuma = min(m, min(min(n, s), min(e, w)));
  float range = maxLuma - minLuma;
#if !FXAA_EDGE_PIXELS
  gOnEdge = range >= max(kEdgeThresholdMin, maxLuma * kEdgeThreshold);
  gCentre = centre;
  return;
#endif
  float ne = lumaOffset(ivec2(1, 1)), nw = lumaOffset(ivec2(-1, 1));
  float se = lumaOffset(ivec2(1, -1)), sw = lumaOffset(ivec2(-1, -1));

  // A horizontal edge changes luma from south to north: second differences across rows against across columns.
  float acrossRows = abs(s + n - 2.0 * m) * 2.0 + abs(se + ne - 2.0 * e) + abs(sw + nw - 2.0 * w);
  float acrossColumns = abs(w + e - 2.0 * m) * 2.0 + abs(nw + ne - 2.0 * n) + abs(sw + se - 2.0 * s);
  bool horizontal = acrossRows >= acrossColumns;

  // The neighbour across the edge: the side with the steeper gradient.
  float before = horizontal ? s : w, after = horizontal ? n : e;
  float gradientBefore = abs(before - m), gradientAfter = abs(after - m);
  bool afterSide = gradientAfter >= gradientBefore;
  float stepLength = afterSide ? 1.0 : -1.0;
  float neighbour = afterSide ? after : before;
  float gradient = 0.25 * max(gradientBefore, gradientAfter);
  float edgeLuma = 0.5 * (m + neighbour);

  // Walk both ways along the edge, on the boundary between the two rows (or columns), until the luma there no
  // longer matches the edge's: those are its ends.
  vec2 across = horizontal ? vec2(0.0, gTexel.y) : vec2(gTexel.x, 0.0);
  vec2 along = horizontal ? vec2(gTexel.x, 0.0) : vec2(0.0, gTexel.y);
  vec2 edgeUv = uv + across * (0.5 * stepLength);
  vec2 uvNeg = edgeUv - along, uvPos = edgeUv + along;
  float endNeg = lumaAt(uvNeg) - edgeLuma, endPos = lumaAt(uvPos) - edgeLuma;
  bool doneNeg = abs(endNeg) >= gradient, donePos = abs(endPos) >= gradient;
  for (int i = 1; i < kSearchSteps && !(doneNeg && donePos); ++i) {
    if (!doneNeg) {
      uvNeg -= along * kStep[i];
      endNeg = lumaAt(uvNeg) - edgeLuma;
      doneNeg = abs(endNeg) >= gradient;
    }
    if (!donePos) {
      uvPos += along * kStep[i];
      endPos = lumaAt(uvPos) - edgeLuma;
      donePos = abs(endPos) >= gradient;
    }
  }
  float distNeg = horizontal ? uv.x - uvNeg.x : uv.y - uvNeg.y;
  float distPos = horizontal ? uvPos.x - uv.x : uvPos.y - uv.y;
  bool negCloser = distNeg < distPos;
  float nearest = min(distNeg, distPos);
  // Only the end where the edge's luma crosses the centre's way blends: the pixel lies on that end's side.
  bool centreBelowEdge = m - edgeLuma < 0.0;
  bool endCrosses = ((negCloser ? endNeg : endPos) < 0.0) != centreBelowEdge;
  float edgeOffset = endCrosses ? 0.5 - nearest / (distNeg + distPos) : 0.0;

  // Sub-pixel aliasing: how far the centre stands out of its 3x3 neighbourhood's low-pass average.
  float average = (2.0 * (n + s + e + w) + ne + nw + se + sw) / 12.0;
  float contrast = clamp(abs(average - m) / range, 0.0, 1.0);
  float smoothed = (-2.0 * contrast + 3.0) * contrast * contrast;
  float subpixelOffset = smoothed * smoothed * kSubpixel;

  float offset = max(edgeOffset, subpixelOffset);
  vec3 filtered = textureLod(displayIn, uv + across * (offset * stepLength), 0.0).rgb;
  imageStore(displayOut, p, vec4(filtered, centre.a));
}

#if FXAA_EDGE_PIXELS
// The listed pixels, striding by the dispatch: the list may hold more than 65,535 workgroups' worth.
void main() {
  ivec2 size = textureSize(displayIn, 0);
  for (uint i = gl_WorkGroupID.x * 64u + gl_LocalInvocationIndex; i < edgeDispatch.w; i += gl_NumWorkGroups.x * 64u) {
    fxaaPixel(ivec2(edgePixels[i] & 0xFFFFu, edgePixels[i] >> 16), size);
  }
}
#else
// Lists this invocation's pixel; the workgroup takes its places at once, and raises the dispatch to cover them (up
// to the 65,535 workgroups a dispatch is sure to take).
shared uint sListed, sFirst;
void listEdge(bool edge, ivec2 p) {
  if (gl_LocalInvocationIndex == 0u) sListed = 0u;
  barrier();
  uint place = edge ? atomicAdd(sListed, 1u) : 0u;
  barrier();
  if (gl_LocalInvocationIndex == 0u && sListed > 0u) {
    sFirst = atomicAdd(edgeDispatch.w, sListed);
    atomicMax(edgeDispatch.x, min((sFirst + sListed + 63u) / 64u, 65535u));
  }
  barrier();
  if (edge) edgePixels[sFirst + place] = uint(p.x) | uint(p.y) << 16;
}

void main() {
  ivec2 size = textureSize(displayIn, 0);
  bool inside = all(lessThan(ivec2(gl_GlobalInvocationID.xy), size));
  ivec2 p = min(ivec2(gl_GlobalInvocationID.xy), size - 1);
  fxaaPixel(p, size);
  listEdge(inside && gOnEdge, p);
  if (inside && !gOnEdge) imageStore(displayOut, p, gCentre);
}
#endif
