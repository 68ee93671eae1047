#include "lighting/shading_model.hpp"

#include <stdexcept>

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
  throw std::invalid_argument("unknown visibility term '" + name + "' (expected exact or hammon)");
}

const char* toString(Visibility visibility) { return visibility == Visibility::HeightCorrelated ? "exact" : "hammon"; }

Culling parseCulling(const std::string& name) {
  if (name == "none") return Culling::None;
  if (name == "clustered") return Culling::Clustered;
  throw std::invalid_argument("unknown culling '" + name + "' (expected none or clustered)");
}

const char* toString(Culling culling) { return culling == Culling::None ? "none" : "clustered"; }

}  // namespace pbr
