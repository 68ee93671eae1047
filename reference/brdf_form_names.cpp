#include "reference/brdf_form_names.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace pbr::reference {

namespace {

template <class Form>
using Names = std::vector<std::pair<Form, const char*>>;

const Names<BrdfForms::Visibility> kVisibilities = {{BrdfForms::Visibility::HeightCorrelated, "exact"},
                                                    {BrdfForms::Visibility::Hammon, "hammon"},
                                                    {BrdfForms::Visibility::Separable, "separable"}};
const Names<BrdfForms::Fresnel> kFresnels = {{BrdfForms::Fresnel::ExactDielectric, "exact"},
                                             {BrdfForms::Fresnel::Schlick, "schlick"},
                                             {BrdfForms::Fresnel::SchlickSG, "schlick-sg"}};
const Names<BrdfForms::Diffuse> kDiffuses = {{BrdfForms::Diffuse::LambertOneMinusFNv, "lambert-1-f"},
                                             {BrdfForms::Diffuse::LambertOneMinusFVh, "lambert-1-f-vh"},
                                             {BrdfForms::Diffuse::Lambert, "lambert"}};

template <class Form>
Form parse(const Names<Form>& names, const std::string& key, const std::string& value) {
  std::string expected;
  for (const auto& [form, name] : names) {
    if (value == name) return form;
    expected += (expected.empty() ? "" : "|") + std::string(name);
  }
  throw std::invalid_argument("the reference has no " + key + " '" + value + "' (expected " + expected + ")");
}

template <class Form>
const char* name(const Names<Form>& names, Form form) {
  return std::find_if(names.begin(), names.end(), [form](const auto& n) { return n.first == form; })->second;
}

}  // namespace

BrdfForms parseBrdfForms(const std::string& text) {
  if (text == "study") return BrdfForms::study();
  BrdfForms forms;
  std::vector<std::string> given;
  size_t start = 0;
  while (start <= text.size() && !text.empty()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    const size_t eq = item.find('=');
    if (item == "study") throw std::invalid_argument("'study' is a whole model and takes no other keys");
    if (eq == std::string::npos) throw std::invalid_argument("variant item '" + item + "' is not key=value");
    const std::string key = item.substr(0, eq) == "vis" ? "visibility" : item.substr(0, eq), value = item.substr(eq + 1);
    if (std::find(given.begin(), given.end(), key) != given.end()) {
      throw std::invalid_argument("variant key '" + key + "' given twice (in '" + text + "')");
    }
    given.push_back(key);
    if (key == "visibility") forms.visibility = parse(kVisibilities, "visibility", value);
    else if (key == "fresnel") forms.fresnel = parse(kFresnels, "fresnel", value);
    else if (key == "diffuse") forms.diffuse = parse(kDiffuses, "diffuse", value);
    else if (key != "ndf" || value != "ggx")
      throw std::invalid_argument("the reference has no form '" + item + "' (keys: visibility, ndf=ggx, fresnel, diffuse)");
    start = end + 1;
  }
  return forms;
}

std::string toString(const BrdfForms& forms) {
  return std::string("visibility=") + name(kVisibilities, forms.visibility) + ",ndf=ggx,fresnel=" +
         name(kFresnels, forms.fresnel) + ",diffuse=" + name(kDiffuses, forms.diffuse);
}

}  // namespace pbr::reference
