#pragma once
#include <string>

#include "reference/reference_brdf.hpp"

namespace pbr::reference {

// The forms as `pbr reference --variant` names them, in the renderer's --variant spelling: "key=value,..." with
// keys visibility (or vis: exact|hammon|separable), ndf (ggx, the only one), fresnel (exact|schlick|schlick-sg)
// and diffuse (lambert-1-f|lambert-1-f-vh|lambert), keys left out keeping the reference model's form; or, alone,
// "study" (BrdfForms::study()). Throws std::invalid_argument.
BrdfForms parseBrdfForms(const std::string& text);
std::string toString(const BrdfForms& forms);  // every key, in the form parseBrdfForms reads

}  // namespace pbr::reference
