#include "app/accuracy/accuracy_variants.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "app/scene_source.hpp"

namespace pbr {

AccuracyVariant::AccuracyVariant(std::string name_, RenderSettings record_)
    : name(std::move(name_)), record(std::move(record_)), settings(frameSettings(record)) {
  for (const auto& entry : record) {
    if (!isFrameSetting(entry.first)) throw std::logic_error("variant " + name + ": " + entry.first + " is no frame setting");
  }
}

PairCostVariant pairCostVariant(const AccuracyVariant& v) {
  PairCostVariant out;
  out.name = v.name;
  out.options = v.settings.frame;
  out.config = v.settings.renderer;
  return out;
}

const std::vector<AccuracyVariant>& accuracyLadder() {
  const RenderSettings::value_type exactFresnel = {"--variant", "fresnel=exact"};
  const RenderSettings::value_type rgba32f = {"--hdr-format", "rgba32f"};
  static const std::vector<AccuracyVariant> ladder = {
      // The reference model's terms: only float precision and the ambient integral differ.
      {"exact", {exactFresnel}},
      {"exact-rgba32f", {exactFresnel, rgba32f}},
      {"exact-float", {exactFresnel, rgba32f, {"--gbuffer", "float"}}},
      {"default", {}},
      {"hammon", {{"--variant", "visibility=hammon"}}},
      {"separable", {{"--variant", "visibility=separable"}}},
      {"beckmann", {{"--variant", "ndf=beckmann"}}},
      {"lambert", {{"--variant", "diffuse=lambert"}}},
      {"burley", {{"--variant", "diffuse=burley"}}},
      {"schlick-sg", {{"--variant", "fresnel=schlick-sg"}}},
      {"lambert-1-f-vh", {{"--variant", "diffuse=lambert-1-f-vh"}}},
      {"study", {{"--variant", "study"}}},
      {"r11g11b10f", {{"--hdr-format", "r11g11b10f"}}},
      {"gbuffer-float", {{"--gbuffer", "float"}}},
      {"fast", {{"--variant", "visibility=hammon,diffuse=lambert"}, {"--hdr-format", "r11g11b10f"}}},
      {"blinn-phong", {{"--model", "blinn-phong"}}},
      {"blinn-phong-sg", {{"--model", "blinn-phong"}, {"--variant", "lobe=sg"}}},
  };
  return ladder;
}

std::vector<AccuracyVariant> selectVariants(const std::string& names) {
  if (names == "all") return accuracyLadder();
  std::vector<AccuracyVariant> out;
  std::stringstream list(names);
  std::string name;
  while (std::getline(list, name, ',')) {
    if (std::any_of(out.begin(), out.end(), [&](const AccuracyVariant& v) { return v.name == name; })) {
      throw std::invalid_argument("variant '" + name + "' given twice (in '" + names + "')");
    }
    bool found = false;
    for (const AccuracyVariant& v : accuracyLadder()) {
      if (v.name == name) {
        out.push_back(v);
        found = true;
      }
    }
    if (!found) {
      std::string known;
      for (const AccuracyVariant& v : accuracyLadder()) known += (known.empty() ? "" : ", ") + v.name;
      throw std::invalid_argument("unknown variant '" + name + "' (expected all or some of: " + known + ")");
    }
  }
  return out;
}

bool hasOnlyAnalyticShapes(const Scene& scene) {
  for (const SceneObject& o : scene.objects)
    if (o.shape == Shape::Mesh) return false;
  return true;
}

AccuracyScene loadAccuracyScene(const std::string& spec, SceneParams params) {
  std::string name = spec, label = spec;
  const size_t colon = spec.find(':');
  if (colon != std::string::npos) {
    name = spec.substr(0, colon);
    const std::string angle = spec.substr(colon + 1);
    char* end = nullptr;
    const float degrees = std::strtof(angle.c_str(), &end);
    if (angle.empty() || end != angle.c_str() + angle.size() || !std::isfinite(degrees)) {
      throw std::invalid_argument("--scenes " + spec + ": expected NAME or fresnel-floor:DEGREES, the view angle a "
                                  "number (got '" + angle + "')");
    }
    if (name != "fresnel-floor") {
      throw std::invalid_argument("--scenes " + spec + ": a view angle applies only to fresnel-floor");
    }
    params.viewAngleDeg = degrees;
    label = name + "-" + angle;
  }
  for (char& c : label)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '_';
  params.defaultEnvironment = DefaultEnvironment::None;  // the reference has no image-based lighting
  Scene scene = resolveScene(name, params);
  for (auto& object : scene.objects) object.material.baseColorTexture = -1;
  return {label, std::move(scene)};
}

const AccuracyVariant& exactVariant() { return accuracyLadder().front(); }

RendererConfig exactVariantConfig() { return exactVariant().settings.renderer; }

FrameOptions exactVariantOptions(const Scene& scene) {
  FrameOptions options = exactVariant().settings.frame;
  options.exposure = scene.displayExposure();
  return options;
}

}  // namespace pbr
