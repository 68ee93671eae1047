#pragma once
#include <string>

namespace pbr {

enum class ShadingModel { Pbr, BlinnPhong };
// The Smith visibility term of the PBR model: exact height-correlated, Hammon's fast approximation, or the
// separable (uncorrelated) product G1(l) G1(v).
enum class Visibility { HeightCorrelated, Hammon, Separable };
enum class Ndf { Ggx, Beckmann };
// Schlick everywhere, or the exact unpolarised term for the dielectric part (metals keep Schlick).
enum class Fresnel { Schlick, Exact };
// Lambert weighted by (1 - F(n.v)), plain Lambert, or Burley's.
enum class Diffuse { LambertOneMinusF, Lambert, Burley };
// Format of the HDR radiance target (the G-buffer's emission attachment and the lighting pass's image).
enum class HdrFormat { Rgba16f, R11g11b10f, Rgba32f };

// One rung of the PBR variant ladder; the default is the renderer's standard model.
struct ShadingVariant {
  Visibility visibility = Visibility::HeightCorrelated;
  Ndf ndf = Ndf::Ggx;
  Fresnel fresnel = Fresnel::Schlick;
  Diffuse diffuse = Diffuse::LambertOneMinusF;
  bool operator==(const ShadingVariant& o) const {
    return visibility == o.visibility && ndf == o.ndf && fresnel == o.fresnel && diffuse == o.diffuse;
  }
};

// Which lights the lighting pass visits per pixel: all of them (the reference path) or its cluster's.
enum class Culling { None, Clustered };

ShadingModel parseShadingModel(const std::string& name);  // "pbr" | "blinn-phong"
const char* toString(ShadingModel model);
Visibility parseVisibility(const std::string& name);  // "exact" | "hammon" | "separable"
const char* toString(Visibility visibility);
// "key=value,..." with keys visibility (or vis), ndf (ggx|beckmann), fresnel (schlick|exact), diffuse
// (lambert-1-f|lambert|burley); keys left out keep the defaults.
ShadingVariant parseShadingVariant(const std::string& text);
std::string toString(const ShadingVariant& variant);  // every key, in the form parseShadingVariant reads
HdrFormat parseHdrFormat(const std::string& name);  // "rgba16f" | "r11g11b10f" | "rgba32f"
const char* toString(HdrFormat format);
unsigned glInternalFormat(HdrFormat format);  // the GLenum
Culling parseCulling(const std::string& name);  // "none" | "clustered"
const char* toString(Culling culling);

}  // namespace pbr
