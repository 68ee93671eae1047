#include "core/scene/shading_model.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

namespace pbr {

ShadingModel parseShadingModel(const std::string& name) {
  if (name == "pbr") return ShadingModel::Pbr;
  if (name == "blinn-phong") return ShadingModel::BlinnPhong;
  throw std::invalid_argument("unknown shading model '" + name + "' (expected pbr or blinn-phong)");
}

const char* toString(ShadingModel model) { return model == ShadingModel::Pbr ? "pbr" : "blinn-phong"; }

namespace {

// Each value of a term with the name --variant reads and the brdf.glsl define that selects it: shaders see
// names only, so reordering an enum cannot change what is shaded.
template <class Term>
struct TermName {
  Term value;
  const char* name;
  const char* define;
};

template <class Term, size_t N>
using TermTable = TermName<Term>[N];

constexpr TermName<Visibility> kVisibilities[] = {
    {Visibility::HeightCorrelated, "exact", "VISIBILITY_EXACT"},
    {Visibility::Hammon, "hammon", "VISIBILITY_HAMMON"},
    {Visibility::Separable, "separable", "VISIBILITY_SEPARABLE"},
};
constexpr TermName<Ndf> kNdfs[] = {
    {Ndf::Ggx, "ggx", "NDF_GGX"},
    {Ndf::Beckmann, "beckmann", "NDF_BECKMANN"},
};
constexpr TermName<Fresnel> kFresnels[] = {
    {Fresnel::Schlick, "schlick", "FRESNEL_SCHLICK"},
    {Fresnel::Exact, "exact", "FRESNEL_EXACT"},
    {Fresnel::SchlickSG, "schlick-sg", "FRESNEL_SCHLICK_SG"},
};
constexpr TermName<Diffuse> kDiffuses[] = {
    {Diffuse::LambertOneMinusF, "lambert-1-f", "DIFFUSE_LAMBERT_1_F"},
    {Diffuse::Lambert, "lambert", "DIFFUSE_LAMBERT"},
    {Diffuse::Burley, "burley", "DIFFUSE_BURLEY"},
    {Diffuse::LambertOneMinusFVh, "lambert-1-f-vh", "DIFFUSE_LAMBERT_1_F_VH"},
};

constexpr TermName<BlinnPhongLobe> kLobes[] = {
    {BlinnPhongLobe::Pow, "pow", "BLINN_PHONG_LOBE_POW"},
    {BlinnPhongLobe::SphericalGaussian, "sg", "BLINN_PHONG_LOBE_SG"},
};

template <class Term, size_t N>
const TermName<Term>& entry(const TermTable<Term, N>& table, Term value) {
  for (const TermName<Term>& t : table)
    if (t.value == value) return t;
  throw std::logic_error("shading term without a name");
}

template <class Term, size_t N>
Term parseTerm(const TermTable<Term, N>& table, const std::string& what, const std::string& name) {
  std::string expected;
  for (size_t i = 0; i < N; ++i) {
    if (table[i].name == name) return table[i].value;
    expected += std::string(i == 0 ? "" : i + 1 == N ? " or " : ", ") + table[i].name;
  }
  throw std::invalid_argument("unknown " + what + " '" + name + "' (expected " + expected + ")");
}

// The PBR model of the Blinn-Phong-vs-PBR study: Hammon's visibility, pow-5 Schlick, Lambert by (1 - F(v.h)).
constexpr ShadingVariant kStudy{Visibility::Hammon, Ndf::Ggx, Fresnel::Schlick, Diffuse::LambertOneMinusFVh};

}  // namespace

Visibility parseVisibility(const std::string& name) { return parseTerm(kVisibilities, "visibility term", name); }

const char* toString(Visibility visibility) { return entry(kVisibilities, visibility).name; }

ShadingVariant parseShadingVariant(const std::string& text, std::vector<std::string>* keys) {
  if (text == "study") {
    if (keys) *keys = {"visibility", "ndf", "fresnel", "diffuse"};
    return kStudy;
  }
  ShadingVariant v;
  std::vector<std::string> given;
  size_t start = 0;
  while (start <= text.size() && !text.empty()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    const size_t eq = item.find('=');
    if (item == "study") throw std::invalid_argument("the variant 'study' is a whole model and takes no other keys");
    if (eq == std::string::npos) throw std::invalid_argument("variant item '" + item + "' is not key=value");
    const std::string key = item.substr(0, eq) == "vis" ? "visibility" : item.substr(0, eq), value = item.substr(eq + 1);
    if (std::find(given.begin(), given.end(), key) != given.end()) {
      throw std::invalid_argument("variant key '" + key + "' given twice (in '" + text + "')");
    }
    given.push_back(key);
    if (key == "visibility") v.visibility = parseVisibility(value);
    else if (key == "ndf") v.ndf = parseTerm(kNdfs, "NDF", value);
    else if (key == "fresnel") v.fresnel = parseTerm(kFresnels, "Fresnel term", value);
    else if (key == "diffuse") v.diffuse = parseTerm(kDiffuses, "diffuse term", value);
    else if (key == "lobe") v.lobe = parseTerm(kLobes, "Blinn-Phong lobe", value);
    else throw std::invalid_argument("unknown variant key '" + key + "' (expected visibility, ndf, fresnel, diffuse, lobe)");
    start = end + 1;
  }
  if (keys) *keys = given;
  return v;
}

std::string toString(const ShadingVariant& v) {
  return std::string("visibility=") + toString(v.visibility) + ",ndf=" + entry(kNdfs, v.ndf).name +
         ",fresnel=" + entry(kFresnels, v.fresnel).name + ",diffuse=" + entry(kDiffuses, v.diffuse).name;
}

ShaderDefines shaderDefines(const ShadingVariant& v) {
  return {{entry(kVisibilities, v.visibility).define, "1"},
          {entry(kNdfs, v.ndf).define, "1"},
          {entry(kFresnels, v.fresnel).define, "1"},
          {entry(kDiffuses, v.diffuse).define, "1"}};
}

std::string toString(BlinnPhongLobe lobe) { return std::string("lobe=") + entry(kLobes, lobe).name; }

std::string describeTerms(ShadingModel model, const ShadingVariant& v) {
  return model == ShadingModel::Pbr ? toString(v) : toString(v.lobe);
}

ShaderDefine blinnPhongDefine(const ShadingVariant& v) { return {entry(kLobes, v.lobe).define, "1"}; }

std::vector<std::string> blinnPhongDefineNames() {
  std::vector<std::string> names;
  for (const auto& t : kLobes) names.push_back(t.define);
  return names;
}

std::vector<std::string> variantDefineNames() {
  std::vector<std::string> names;
  for (const auto& t : kVisibilities) names.push_back(t.define);
  for (const auto& t : kNdfs) names.push_back(t.define);
  for (const auto& t : kFresnels) names.push_back(t.define);
  for (const auto& t : kDiffuses) names.push_back(t.define);
  return names;
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

Culling parseCulling(const std::string& name) {
  if (name == "none") return Culling::None;
  if (name == "clustered") return Culling::Clustered;
  if (name == "auto") return Culling::Auto;
  throw std::invalid_argument("unknown culling '" + name + "' (expected none, clustered or auto)");
}

const char* toString(Culling culling) {
  switch (culling) {
    case Culling::None: return "none";
    case Culling::Clustered: return "clustered";
    case Culling::Auto: return "auto";
  }
  return "?";
}

}  // namespace pbr
