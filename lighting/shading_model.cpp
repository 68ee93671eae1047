#include "lighting/shading_model.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/gl.hpp"

namespace pbr {

ShadingModel parseShadingModel(const std::string& name) {
  if (name == "pbr") return ShadingModel::Pbr;
  if (name == "blinn-phong") return ShadingModel::BlinnPhong;
  throw std::invalid_argument("unknown shading model '" + name + "' (expected pbr or blinn-phong)");
}

const char* toString(ShadingModel model) { return model == ShadingModel::Pbr ? "pbr" : "blinn-phong"; }

Visibility parseVisibility(const std::string& name) {
  if (name == "exact") return Visibility::HeightCorrelated;
  if (name == "hammon") return Visibility::Hammon;
  if (name == "separable") return Visibility::Separable;
  throw std::invalid_argument("unknown visibility term '" + name + "' (expected exact, hammon or separable)");
}

const char* toString(Visibility visibility) {
  switch (visibility) {
    case Visibility::HeightCorrelated: return "exact";
    case Visibility::Hammon: return "hammon";
    case Visibility::Separable: return "separable";
  }
  return "?";
}

namespace {

Ndf parseNdf(const std::string& name) {
  if (name == "ggx") return Ndf::Ggx;
  if (name == "beckmann") return Ndf::Beckmann;
  throw std::invalid_argument("unknown NDF '" + name + "' (expected ggx or beckmann)");
}

Fresnel parseFresnel(const std::string& name) {
  if (name == "schlick") return Fresnel::Schlick;
  if (name == "exact") return Fresnel::Exact;
  throw std::invalid_argument("unknown Fresnel term '" + name + "' (expected schlick or exact)");
}

Diffuse parseDiffuse(const std::string& name) {
  if (name == "lambert-1-f") return Diffuse::LambertOneMinusF;
  if (name == "lambert") return Diffuse::Lambert;
  if (name == "burley") return Diffuse::Burley;
  throw std::invalid_argument("unknown diffuse term '" + name + "' (expected lambert-1-f, lambert or burley)");
}

const char* toString(Diffuse d) {
  switch (d) {
    case Diffuse::LambertOneMinusF: return "lambert-1-f";
    case Diffuse::Lambert: return "lambert";
    case Diffuse::Burley: return "burley";
  }
  return "?";
}

}  // namespace

ShadingVariant parseShadingVariant(const std::string& text) {
  ShadingVariant v;
  size_t start = 0;
  while (start <= text.size() && !text.empty()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    const size_t eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("variant item '" + item + "' is not key=value");
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    if (key == "visibility" || key == "vis") v.visibility = parseVisibility(value);
    else if (key == "ndf") v.ndf = parseNdf(value);
    else if (key == "fresnel") v.fresnel = parseFresnel(value);
    else if (key == "diffuse") v.diffuse = parseDiffuse(value);
    else throw std::invalid_argument("unknown variant key '" + key + "' (expected visibility, ndf, fresnel, diffuse)");
    start = end + 1;
  }
  return v;
}

std::string toString(const ShadingVariant& v) {
  return std::string("visibility=") + toString(v.visibility) + ",ndf=" + (v.ndf == Ndf::Ggx ? "ggx" : "beckmann") +
         ",fresnel=" + (v.fresnel == Fresnel::Schlick ? "schlick" : "exact") + ",diffuse=" + toString(v.diffuse);
}

HdrFormat parseHdrFormat(const std::string& name) {
  if (name == "rgba16f") return HdrFormat::Rgba16f;
  if (name == "r11g11b10f") return HdrFormat::R11g11b10f;
  if (name == "rgba32f") return HdrFormat::Rgba32f;
  throw std::invalid_argument("unknown HDR format '" + name + "' (expected rgba16f, r11g11b10f or rgba32f)");
}

const char* toString(HdrFormat format) {
  switch (format) {
    case HdrFormat::Rgba16f: return "rgba16f";
    case HdrFormat::R11g11b10f: return "r11g11b10f";
    case HdrFormat::Rgba32f: return "rgba32f";
  }
  return "?";
}

unsigned glInternalFormat(HdrFormat format) {
  switch (format) {
    case HdrFormat::Rgba16f: return GL_RGBA16F;
    case HdrFormat::R11g11b10f: return GL_R11F_G11F_B10F;
    case HdrFormat::Rgba32f: return GL_RGBA32F;
  }
  return GL_RGBA16F;
}

Culling parseCulling(const std::string& name) {
  if (name == "none") return Culling::None;
  if (name == "clustered") return Culling::Clustered;
  throw std::invalid_argument("unknown culling '" + name + "' (expected none or clustered)");
}

const char* toString(Culling culling) { return culling == Culling::None ? "none" : "clustered"; }

}  // namespace pbr
