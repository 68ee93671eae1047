#pragma once
#include <string>

#include "reference/reference_brdf.hpp"

namespace pbr::reference {

// The forms as `pbr reference --variant` names them: the renderer's --variant, read by its parser
// (parseShadingVariant), keys left out keeping the reference model's form; or, alone, "study". Throws
// std::invalid_argument for what the parser refuses and for the terms the reference cannot evaluate (BrdfForms).
BrdfForms parseBrdfForms(const std::string& text);
std::string toString(const BrdfForms& forms);  // every key, in the form parseBrdfForms reads

}  // namespace pbr::reference
