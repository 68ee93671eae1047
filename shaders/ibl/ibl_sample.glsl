// Image-based lighting for the lighting pass: the maps pbr::IblMaps precomputes, bound by bindEnvironmentMaps
// (core/gl/environment_maps.hpp) at the points its table defines:
//   IBL_UBO            IblBlock: 9 spherical-harmonic radiance coefficients of the environment (diffuse)
//   IBL_SPECULAR_UNIT  GGX-prefiltered radiance cube map, RGBA16F; level k holds roughness k / (levels - 1)
//   IBL_DFG_UNIT       split-sum DFG table, RG16F, x = n.v, y = perceptual roughness
// IBL_MULTIPLE_SCATTERING 1 adds the multiple-scattering energy compensation to shadeIbl.
#include "../lighting/brdf.glsl"
#include "sh9.glsl"

#ifndef IBL_MULTIPLE_SCATTERING
#define IBL_MULTIPLE_SCATTERING 0
#endif

// Mirrors pbr::IblBlock (ibl/irradiance_sh.hpp).
layout(std140, binding = IBL_UBO) uniform IblBlock {
  vec4 sh[9];  // rgb: radiance coefficients in the order of sh9.glsl
} ibl;

layout(binding = IBL_SPECULAR_UNIT) uniform samplerCube iblSpecularMap;
layout(binding = IBL_DFG_UNIT) uniform sampler2D iblDfgTable;

// Irradiance E(N) = integral of L(w) max(N.w, 0) dw; band-2 ringing below an isolated bright source can dip under
// zero, which no irradiance can.
vec3 iblIrradiance(vec3 N) { return max(shIrradiance9(N, ibl.sh), vec3(0.0)); }

// Radiance a white Lambertian surface reflects, E / pi: the caller multiplies by its diffuse albedo.
vec3 iblDiffuse(vec3 N) { return iblIrradiance(N) / PI; }

// Environment radiance around R prefiltered by the GGX lobe of a perceptual roughness, between the two levels
// that bracket it. Level 0 is the unfiltered environment, which also serves as the background.
vec3 iblSpecular(vec3 R, float roughness) {
  float lod = saturate(roughness) * float(textureQueryLevels(iblSpecularMap) - 1);
  return textureLod(iblSpecularMap, R, lod).rgb;
}

#if MATERIAL_SHEEN
// KHR_materials_sheen: the environment prefiltered by the Charlie lobe (ibl/sheen_prefilter.hpp), level k at sheen
// roughness k / (levels - 1), between the two levels that bracket it; the sheen table's E scales it.
layout(binding = IBL_SHEEN_UNIT) uniform samplerCube iblSheenMap;
vec3 iblSheen(vec3 N, float sheenRoughness) {
  float lod = saturate(sheenRoughness) * float(textureQueryLevels(iblSheenMap) - 1);
  return textureLod(iblSheenMap, N, lod).rgb;
}
#endif

// (A, B) with F0 A + B the directional albedo of the specular lobe (Karis 2013, "Real Shading in Unreal
// Engine 4"); texel centres lie on the ends of both ranges (ibl/dfg.comp).
vec2 iblDfg(float NoV, float roughness) {
  vec2 size = vec2(textureSize(iblDfgTable, 0));
  vec2 uv = tableUv(vec2(NoV, roughness), size);
  return textureLod(iblDfgTable, uv, 0.0).rg;
}

// Factor on the single-scattering specular lobe that restores the energy lost to masking, from the F0 = 1
// albedo A + B: 1 + F0 (1 / (A + B) - 1) (Turquin 2019, "Practical multiple scattering compensation for
// microfacet models"; the form Filament uses).
vec3 iblEnergyCompensation(vec3 F0, vec2 dfg) { return 1.0 + F0 * (1.0 / (dfg.x + dfg.y) - 1.0); }

// Split-sum image-based lighting of the renderer's material (glTF metal-rough): specular F0 A + B times the
// prefiltered radiance; Lambert diffuse weighted, like the direct lighting, by (1 - F)(1 - metalness) with F the
// specular albedo F0 A + B, so that a white dielectric in a uniform environment reflects exactly that radiance.
// Occlusion scales both terms, as it does the renderer's ambient term.
vec3 shadeIbl(vec3 N, vec3 V, vec3 baseColor, float roughness, float metalness, float occlusion) {
  float NoV = max(dot(N, V), 1e-4);
  vec2 dfg = iblDfg(NoV, roughness);
#if MATERIAL_SPECULAR
  // KHR_materials_ior / _specular: F0 A + F90 B; the diffuse is weighted by the albedo of the dielectric's largest
  // channel, as glTF's fresnel_mix weights it by max_value(F).
  vec3 F0 = mix(gDielectric.rgb, baseColor, metalness);
  float F90 = gDielectric.a + (1.0 - gDielectric.a) * metalness;
  float largest = max(gDielectric.r, max(gDielectric.g, gDielectric.b));
  vec3 specularAlbedo = F0 * dfg.x + F90 * dfg.y;
  vec3 weightAlbedo = mix(vec3(largest), baseColor, metalness) * dfg.x + F90 * dfg.y;
#if IBL_MULTIPLE_SCATTERING
  specularAlbedo *= iblEnergyCompensation(F0, dfg);
  weightAlbedo *= iblEnergyCompensation(mix(vec3(largest), baseColor, metalness), dfg);
#endif
#else
  vec3 F0 = f0FromMaterial(baseColor, metalness);
  vec3 specularAlbedo = F0 * dfg.x + dfg.y;
#if IBL_MULTIPLE_SCATTERING
  specularAlbedo *= iblEnergyCompensation(F0, dfg);
#endif
  vec3 weightAlbedo = specularAlbedo;
#endif
  vec3 specular = specularAlbedo * iblSpecular(reflect(-V, N), roughness);
#if MATERIAL_TRANSMISSION
  // KHR_materials_transmission: the base's share gTransmission shows what lies behind instead of diffusing.
  vec3 diffuse = (1.0 - weightAlbedo) * (1.0 - metalness) * baseColor * mix(iblDiffuse(N), gBehind, gTransmission);
#else
  vec3 diffuse = (1.0 - weightAlbedo) * (1.0 - metalness) * baseColor * iblDiffuse(N);
#endif
  return (diffuse + specular) * occlusion;
}
