// The PBR shading model: Cook-Torrance GGX, photometric point lights, HDR output.
#include "brdf.glsl"

vec3 shadeAmbient(Surface s) {
  // Uniform ambient radiance: Lambert integrates to the albedo and the specular lobe to about F0.
  vec3 F0 = f0FromMaterial(s.baseColor, s.metalness);
  vec3 diffuse = (1.0 - s.metalness) * s.baseColor * (1.0 - F0);
  return lighting.ambient.rgb * (diffuse + F0) * s.occlusion;
}

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
