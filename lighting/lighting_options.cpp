#include "lighting/lighting_options.hpp"

#include <string>
#include <utility>

#include "core/scene/binding_table.hpp"

namespace pbr {

std::pair<const char*, const char*> radianceImageFormat(HdrFormat format) {
  switch (format) {
    case HdrFormat::R11g11b10f: return {"r11f_g11f_b10f", "64512.0"};  // the 10-bit blue channel's maximum
    case HdrFormat::Rgba32f: return {"rgba32f", "FP16_MAX"};
    case HdrFormat::Rgba16f: break;
  }
  return {"rgba16f", "FP16_MAX"};
}

ShaderDefines lightingPermutation(const LightingOptions& o, bool clustered, HdrFormat radiance, bool chunked,
                                  LightKinds kinds, uint32_t lightWindow) {
  const bool blinnPhong = o.model == ShadingModel::BlinnPhong;
  auto flag = [](bool b) { return std::string(b ? "1" : "0"); };
  const auto [qualifier, maximum] = radianceImageFormat(radiance);
  // Each model sees only its own terms, so that a term of the other model never splits a permutation.
  ShaderDefines defines = shaderDefines(blinnPhong ? ShadingVariant{} : o.variant);
  if (blinnPhong) defines.push_back(blinnPhongDefine(o.variant));
  defines.insert(defines.begin(), {"SHADING_MODEL_BLINN_PHONG", flag(blinnPhong)});
  defines.push_back({"HDR_IMAGE_FORMAT", qualifier});
  defines.push_back({"HDR_MAX", maximum});
  defines.push_back({"CLUSTERED", flag(clustered)});
  defines.push_back({"LIGHTING_STATS", flag(o.stats)});
  defines.push_back({"LIGHTING_PAIR_IMAGE", flag(o.pairCounts != nullptr)});
  defines.push_back({"IBL", flag(o.ibl())});
  defines.push_back({"LIGHT_CHUNKS", flag(chunked)});
  defines.push_back({"SPOT_LIGHTS", flag(kinds.spot)});
  defines.push_back({"DIRECTIONAL_LIGHTS", std::to_string(kinds.directional)});
  defines.push_back({"SHADOWS", flag(o.shadows != nullptr)});
  defines.push_back({"UNLIT_MATERIALS", flag(o.unlitSurfaces)});
  defines.push_back({"MATERIAL_SPECULAR", flag(o.specularMaterials && !blinnPhong)});
  defines.push_back({"MATERIAL_CLEARCOAT", flag(o.clearcoatMaterials && !blinnPhong)});
  defines.push_back({"MATERIAL_SHEEN", flag(o.sheenMaterials && !blinnPhong)});
  // Named only when on, so that the permutations of frames that shade the lobe keep their define lists.
  if (o.transmissionOff) defines.push_back({"TRANSMISSION_OFF", "1"});
  if (o.shadows) {
    defines.push_back({shadowFilterDefine(o.shadowFilter), "1"});
    defines = concat(defines, shadowViewDefines());
  }
  defines.push_back({"SHADOW_LIGHT_IMAGE", flag(o.shadows && o.shadowLight)});
  if (!clustered) defines.push_back({"LIGHT_WINDOW", std::to_string(lightWindow)});
  defines.push_back({"MAX_DIRECTIONAL_LIGHTS", std::to_string(kMaxDirectionalLights)});
  return defines;
}

MaterialLobes usedLobes(const Scene& scene) {
  MaterialLobes used{false, false, false, false};
  for (const SceneObject& o : scene.objects) {
    const Material& m = o.material;
    used.specular = used.specular || hasDielectricSpecular(m);
    used.clearcoat = used.clearcoat || hasClearcoat(m);
    used.sheen = used.sheen || hasSheen(m);
    used.transmission = used.transmission || isTransmissive(m);
  }
  return used;
}

}  // namespace pbr
