#include "reference/brdf_form_names.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace pbr::reference {

BrdfForms parseBrdfForms(const std::string& text) {
  std::vector<std::string> keys;
  const ShadingVariant parsed = parseShadingVariant(text, &keys);
  // Keys left out keep the reference model's forms, not the renderer's defaults.
  BrdfForms forms;
  for (const std::string& key : keys) {
    if (key == "visibility") forms.visibility = parsed.visibility;
    if (key == "ndf") forms.ndf = parsed.ndf;
    if (key == "fresnel") forms.fresnel = parsed.fresnel;
    if (key == "diffuse") forms.diffuse = parsed.diffuse;
    if (key == "lobe") throw std::invalid_argument("lobe is a term of the blinn-phong model; the reference is PBR");
  }
  return BrdfForms(static_cast<const ShadingVariant&>(forms));  // refuses the terms it cannot evaluate
}

std::string toString(const BrdfForms& forms) { return toString(static_cast<const ShadingVariant&>(forms)); }

}  // namespace pbr::reference
