// The PBR shading model: Cook-Torrance GGX, photometric point lights, HDR output.
#include "brdf.glsl"

#if !IBL
// The variant's own directional albedo (lighting/ambient_albedo.comp): x, y the specular lobe for metals as
// F0 A + B, z for the dielectric, w the diffuse weight's mean; texel centres on the range ends.
layout(binding = AMBIENT_ALBEDO_UNIT) uniform sampler2D ambientAlbedo;

// Uniform ambient radiance times the directional albedo of the whole BRDF, f n.l integrated over the hemisphere.
vec3 shadeAmbient(Surface s) {
  vec2 size = vec2(textureSize(ambientAlbedo, 0));
  vec2 uv = (vec2(saturate(s.NoV), saturate(s.roughness)) * (size - 1.0) + 0.5) / size;
  vec4 t = textureLod(ambientAlbedo, uv, 0.0);
  vec3 specular = (1.0 - s.metalness) * t.z + s.metalness * (s.baseColor * t.x + t.y);
#if defined(DIFFUSE_LAMBERT_1_F)
  vec3 weight = 1.0 - fresnel(s.baseColor, s.metalness, s.NoV);  // constant over the hemisphere: exact
#elif defined(DIFFUSE_LAMBERT)
  vec3 weight = vec3(1.0);
#else
  vec3 weight = vec3(t.w);  // a dielectric's: exact for metalness 0 and 1, interpolated between
#endif
  return lighting.ambient.rgb * (weight * (1.0 - s.metalness) * s.baseColor + specular) * s.occlusion;
}
#endif

// Nothing per pixel is shared between lights yet: the BRDF takes the surface as it is.
void beginShading(Surface s) {}

vec3 shadeLight(Surface s, PointLight light) {
  float d;
  vec3 L = directionToLight(s.position, s.normal, light, d);
  float NoL = dot(s.normal, L);
  float att = distanceAttenuation(d, light.positionRadius.w);
  if (NoL <= 0.0 || att <= 0.0) return vec3(0.0);
  vec3 f = brdfCookTorrance(s.normal, s.V, L, s.NoV, s.baseColor, s.roughness, s.metalness);
  return f * light.colorIntensity.rgb * (light.colorIntensity.w * att * NoL);
}

vec3 finishShading(vec3 color) { return min(color, vec3(FP16_MAX)); }
