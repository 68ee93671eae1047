#include "app/accuracy/accuracy_variants.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "app/scene_source.hpp"

namespace pbr {

namespace {

AccuracyVariant pbrVariant(const std::string& name, const std::string& terms, HdrFormat hdr = HdrFormat::Rgba16f,
                           GBufferPrecision gbuffer = GBufferPrecision::Lean) {
  return {name, ShadingModel::Pbr, parseShadingVariant(terms), hdr, gbuffer};
}

}  // namespace

PairCostVariant pairCostVariant(const AccuracyVariant& v) {
  PairCostVariant out;
  out.name = v.name;
  out.options.model = v.model;
  out.options.variant = v.shading;
  out.config.hdrFormat = v.hdr;
  out.config.gbuffer = v.gbuffer;
  return out;
}

const std::vector<AccuracyVariant>& accuracyLadder() {
  static const std::vector<AccuracyVariant> ladder = {
      // The reference model's terms: only float precision and the ambient integral differ.
      pbrVariant("exact", "fresnel=exact"),
      pbrVariant("exact-rgba32f", "fresnel=exact", HdrFormat::Rgba32f),
      pbrVariant("exact-float", "fresnel=exact", HdrFormat::Rgba32f, GBufferPrecision::Float),
      pbrVariant("default", ""),
      pbrVariant("hammon", "visibility=hammon"),
      pbrVariant("separable", "visibility=separable"),
      pbrVariant("beckmann", "ndf=beckmann"),
      pbrVariant("lambert", "diffuse=lambert"),
      pbrVariant("burley", "diffuse=burley"),
      pbrVariant("schlick-sg", "fresnel=schlick-sg"),
      pbrVariant("lambert-1-f-vh", "diffuse=lambert-1-f-vh"),
      pbrVariant("study", "study"),
      pbrVariant("r11g11b10f", "", HdrFormat::R11g11b10f),
      pbrVariant("gbuffer-float", "", HdrFormat::Rgba16f, GBufferPrecision::Float),
      pbrVariant("fast", "visibility=hammon,diffuse=lambert", HdrFormat::R11g11b10f),
      {"blinn-phong", ShadingModel::BlinnPhong, {}, HdrFormat::Rgba16f, GBufferPrecision::Lean},
      {"blinn-phong-sg", ShadingModel::BlinnPhong, parseShadingVariant("lobe=sg"), HdrFormat::Rgba16f,
       GBufferPrecision::Lean},
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

RendererConfig exactVariantConfig() {
  RendererConfig config;
  config.hdrFormat = exactVariant().hdr;
  config.gbuffer = exactVariant().gbuffer;
  return config;
}

FrameOptions exactVariantOptions(const Scene& scene) {
  FrameOptions options;
  options.model = exactVariant().model;
  options.variant = exactVariant().shading;
  options.exposure = scene.displayExposure();
  return options;
}

}  // namespace pbr
