#version 450 core
// Forward lighting of a BLEND or transmissive material's fragment, drawn after the deferred pass over the radiance
// it left: the material (../gbuffer/material.glsl) lit by the same lights, lists, models, environment and shadows
// as the deferred pass (shade_lights.glsl), written premultiplied by its alpha for the blend unit's
// src + (1 - src.a) dst, the "over" of Porter & Duff 1984, "Compositing Digital Images". With LIGHT_CHUNKS a draw
// adds one chunk of the lights: the first also brings the environment, the directional lights and the emission,
// and the alpha that composites; the others write alpha 0 and so add to it. With MATERIAL_TRANSMISSION the surface
// also shows the opaque frame behind it (transmission.glsl) through the model's transmission terms (brdf.glsl,
// model_pbr.glsl, ibl_sample.glsl).
// With OIT_WEIGHTED the fragment is instead summed into weighted blended order-independent transparency's targets
// (McGuire & Bavoil 2013), resolved by oit_composite.comp; with OIT_EXACT it is kept in its pixel's list
// (layer_lists.glsl), resolved by layer_resolve.comp.
#if TRANSMISSION_OFF
// MaterialLobes::transmission off: a transmissive material shaded as if without the extension.
#undef MATERIAL_TRANSMISSION
#define MATERIAL_TRANSMISSION 0
#endif
#include "../gbuffer/material.glsl"
#include "shade_lights.glsl"
#if MATERIAL_TRANSMISSION
#include "transmission.glsl"
#endif

#if OIT_EXACT
#include "layer_lists.glsl"
// Fragments behind the opaque surface must not take a node: the depth test before the shader runs.
layout(early_fragment_tests) in;
#elif OIT_WEIGHTED
layout(location = 0) out vec4 outAccumulation;  // blended ONE, ONE: w a C, w a
layout(location = 1) out vec4 outRevealage;     // blended ZERO, ONE_MINUS_SRC_COLOR: the target keeps its 1 - a

// McGuire & Bavoil 2013, eq. 7: nearer layers weigh more, so that the average leans to the front one, for view
// depths z in metres from centimetres to hundreds of metres.
float depthWeight(float z) { return clamp(10.0 / (1e-5 + pow(z / 5.0, 2.0) + pow(z / 200.0, 6.0)), 1e-2, 3e3); }
#else
layout(location = 0) out vec4 outColor;
#endif

void main() {
  MaterialSample m = sampleMaterial();
  Surface s;
  // The point the G-buffer would hold here: the same reconstruction, so the same cluster as the occupancy found.
  placeSurface(viewPositionAt(floor(gl_FragCoord.xy), gl_FragCoord.z), m.normal, s);
  s.baseColor = m.base.rgb;
  s.roughness = m.roughness;
  s.metalness = m.metalness;
  s.occlusion = m.occlusion;
#if MATERIAL_SPECULAR
  s.dielectric = m.dielectric;
#endif
#if MATERIAL_CLEARCOAT
  s.clearcoat = m.clearcoat;
  s.clearcoatRoughness = m.clearcoatRoughness;
  s.clearcoatNormal = m.clearcoatNormal;
#endif
#if MATERIAL_SHEEN
  s.sheenColor = m.sheenColor;
  s.sheenRoughness = m.sheenRoughness;
#endif
#if MATERIAL_TRANSMISSION && !SHADING_MODEL_BLINN_PHONG
  // Before beginShading, which weighs the diffuse lobe by it.
  gTransmission = m.transmission;
#endif
  beginShading(s);
  uint count = lightsToVisit(s, uvec2(gl_FragCoord.xy));
#if LIGHT_CHUNKS
  bool first = lightChunk.z != 0u;
  uint begin = min(lightChunk.x, count), end = min(lightChunk.y, count);
#else
  bool first = true;
  uint begin = 0u, end = count;
#endif
#if MATERIAL_TRANSMISSION && !SHADING_MODEL_BLINN_PHONG
  // What lies behind reaches the surface through the environment's term, which the first chunk alone adds.
  if (first) gBehind = transmittedRadiance(s, m.thickness);
#endif
#if UNLIT
  // KHR_materials_unlit: the base colour is the radiance, with no light added.
  gColor = first ? m.base.rgb : vec3(0.0);
#else
#if MATERIAL_CLEARCOAT
  gColor = first ? m.emitted * coatTransmission(s) + shadeEnvironment(s) : vec3(0.0);
#else
  gColor = first ? m.emitted + shadeEnvironment(s) : vec3(0.0);
#endif
  visitLights(s, begin, end);
#if MATERIAL_TRANSMISSION && SHADING_MODEL_BLINN_PHONG
  // Blinn-Phong has no Fresnel to share light by: the transmitted share replaces that of the lit colour.
  vec3 through = first ? m.transmission * m.base.rgb * transmittedRadiance(s, m.thickness) : vec3(0.0);
  gColor = gColor * (1.0 - m.transmission) + through;
#endif
#endif
  // NaN compares false everywhere: keep only values known to be finite and non-negative.
  vec3 color = mix(vec3(0.0), gColor, greaterThanEqual(gColor, vec3(0.0)));
  float alpha = clamp(m.base.a, 0.0, 1.0);
  vec3 lit = min(finishShading(color), vec3(HDR_MAX));
#if OIT_EXACT
  // A later chunk of the lights adds its colour with alpha 0 at the same depth: the resolve composites it before
  // its layer's first node, under the same coverage. Helper invocations (the quad's lanes outside the triangle, run
  // for derivatives) take no node.
  if (!gl_HelperInvocation) {
    uint node = atomicAdd(nodeCount, 1u);
    if (node < nodeCapacity) {
      uvec2 p = uvec2(gl_FragCoord.xy);
      uint next = atomicExchange(words[p.y * uint(frame.viewport.x) + p.x], node + 1u);
      vec3 c = lit * alpha;
      uint at = heads + 4u * node;
      words[at] = packHalf2x16(c.rg);
      words[at + 1u] = packHalf2x16(vec2(c.b, first ? alpha : 0.0));
      words[at + 2u] = floatBitsToUint(gl_FragCoord.z);
      words[at + 3u] = next;
    } else {
      atomicAdd(droppedNodes, 1u);
    }
  }
#elif OIT_WEIGHTED
  float w = alpha * depthWeight(s.viewDepth);
  outAccumulation = vec4(lit * w, first ? w : 0.0);
  outRevealage = vec4(first ? alpha : 0.0);
#else
  outColor = vec4(lit * alpha, first ? alpha : 0.0);
#endif
}
