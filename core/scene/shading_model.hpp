#pragma once
#include <string>
#include <vector>

#include "core/scene/shader_sources.hpp"

namespace pbr {

enum class ShadingModel { Pbr, BlinnPhong };
// The Smith visibility term of the PBR model: exact height-correlated, Hammon's fast approximation, or the
// separable (uncorrelated) product G1(l) G1(v).
enum class Visibility { HeightCorrelated, Hammon, Separable };
enum class Ndf { Ggx, Beckmann };
// Schlick everywhere, the exact unpolarised term for the dielectric part (metals keep Schlick), or Schlick with
// the power replaced by a spherical Gaussian everywhere.
enum class Fresnel { Schlick, Exact, SchlickSG };
// Lambert weighted by (1 - F(n.v)), plain Lambert, Burley's, or Lambert weighted by (1 - F(v.h)).
enum class Diffuse { LambertOneMinusF, Lambert, Burley, LambertOneMinusFVh };
// The Blinn-Phong specular lobe (n.h)^n: the power itself, or its spherical-Gaussian approximation e^(n (n.h - 1)).
enum class BlinnPhongLobe { Pow, SphericalGaussian };
// Format of the HDR radiance target (the G-buffer's emission attachment and the lighting pass's image).
enum class HdrFormat { Rgba16f, R11g11b10f, Rgba32f };

// One rung of the variant ladder; the default is the renderer's standard model. The first four terms are the
// PBR model's, `lobe` the Blinn-Phong model's.
struct ShadingVariant {
  Visibility visibility = Visibility::HeightCorrelated;
  Ndf ndf = Ndf::Ggx;
  Fresnel fresnel = Fresnel::Schlick;
  Diffuse diffuse = Diffuse::LambertOneMinusF;
  BlinnPhongLobe lobe = BlinnPhongLobe::Pow;
  bool operator==(const ShadingVariant& o) const {
    return visibility == o.visibility && ndf == o.ndf && fresnel == o.fresnel && diffuse == o.diffuse &&
           lobe == o.lobe;
  }
};

// Which lights the lighting pass visits per pixel: all of them (the reference path) or its cluster's; Auto, a
// request only, runs per frame whichever the renderer predicts cheaper (renderer/culling_choice.hpp).
enum class Culling { None, Clustered, Auto };

ShadingModel parseShadingModel(const std::string& name);  // "pbr" | "blinn-phong"
const char* toString(ShadingModel model);
Visibility parseVisibility(const std::string& name);  // "exact" | "hammon" | "separable"
const char* toString(Visibility visibility);
// "key=value,..." with keys visibility (or vis), ndf (ggx|beckmann), fresnel (schlick|exact|schlick-sg), diffuse
// (lambert-1-f|lambert|burley|lambert-1-f-vh) and, for Blinn-Phong, lobe (pow|sg); keys left out keep the defaults. Or, alone, "study": the PBR
// model of the Blinn-Phong-vs-PBR study, visibility=hammon,ndf=ggx,fresnel=schlick,diffuse=lambert-1-f-vh.
// `keys`, when given, receives the keys the text sets ("visibility" for "vis"; the four PBR keys for "study"); a key
// given twice is refused.
ShadingVariant parseShadingVariant(const std::string& text, std::vector<std::string>* keys = nullptr);
std::string toString(const ShadingVariant& variant);  // every PBR key, in the form parseShadingVariant reads
std::string toString(BlinnPhongLobe lobe);            // "lobe=pow" | "lobe=sg"
// The terms `model` uses: the PBR keys, or the Blinn-Phong lobe.
std::string describeTerms(ShadingModel model, const ShadingVariant& variant);
// The defines that select the variant's terms in shaders/lighting/brdf.glsl: one per term, named for the chosen
// value (VISIBILITY_HAMMON, FRESNEL_SCHLICK_SG, ...) and defined to 1.
ShaderDefines shaderDefines(const ShadingVariant& variant);
// Every define name shaderDefines can produce, for checking them against brdf.glsl.
std::vector<std::string> variantDefineNames();
// The define of the Blinn-Phong lobe (BLINN_PHONG_LOBE_POW, ...) for shaders/lighting/model_blinn_phong.glsl, and
// every name it can take.
ShaderDefine blinnPhongDefine(const ShadingVariant& variant);
std::vector<std::string> blinnPhongDefineNames();
HdrFormat parseHdrFormat(const std::string& name);  // "rgba16f" | "r11g11b10f" | "rgba32f"
const char* toString(HdrFormat format);
Culling parseCulling(const std::string& name);  // "none" | "clustered" | "auto"
const char* toString(Culling culling);

}  // namespace pbr
