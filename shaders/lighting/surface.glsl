// A shaded surface point, as the deferred pass reads it from the G-buffer (gbuffer_surface.glsl) and the forward
// pass from a BLEND material's fragment (forward.frag).
#include "../common/frame.glsl"

struct Surface {
  vec3 position;      // world
  float viewDepth;    // distance along the view axis (-z in view space)
  vec3 normal;
  float NoV;          // clamped away from 0 so that grazing pixels stay finite
  vec3 V;             // unit vector to the camera
  float roughness;    // perceptual
  vec3 baseColor;
  float metalness;
  float occlusion;    // of the ambient term only: point lights are direct light
#if UNLIT_MATERIALS
  bool unlit;         // KHR_materials_unlit: its radiance is in the radiance target already, no light is added
#endif
#if MATERIAL_SPECULAR
  vec4 dielectric;    // KHR_materials_ior / _specular: the dielectric's F0 colour (rgb) and F90 (a)
#endif
#if MATERIAL_CLEARCOAT
  float clearcoat;    // KHR_materials_clearcoat: the coat's strength (0: none), perceptual roughness and normal
  float clearcoatRoughness;
  vec3 clearcoatNormal;
#endif
#if MATERIAL_SHEEN
  vec3 sheenColor;    // KHR_materials_sheen: the fibre lobe's colour (black: none) and roughness
  float sheenRoughness;
#endif
};

// The point's place and view terms from its view-space position and unit normal.
void placeSurface(vec3 viewPos, vec3 normal, inout Surface s) {
  s.position = (frame.inverseView * vec4(viewPos, 1.0)).xyz;
  s.viewDepth = -viewPos.z;
  s.normal = normal;
  s.V = normalize(towardsViewer(s.position));
  s.NoV = max(dot(s.normal, s.V), 1e-4);
}
