#include "core/scene/gltf_material.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <utility>

#include "core/scene/gltf_accessor.hpp"
#include "core/scene/gltf_uri.hpp"
#include "core/scene/image.hpp"

namespace pbr {

namespace {

float finite(const GltfFile& file, double v, const std::string& field) {
  // A double such as 1e300 is finite but not as a float.
  if (!std::isfinite(static_cast<float>(v))) file.fail(field + ": must be a finite number within float range");
  return static_cast<float>(v);
}

// An extension's number at `where`, which JSON may give as anything.
float number(const GltfFile& file, const tinygltf::Value& v, const std::string& where) {
  if (!v.IsNumber()) file.fail(where + ": must be a number");
  return finite(file, v.GetNumberAsDouble(), where);
}

// glTF factors in [0,1]; exporters print values a rounding error outside, which are clamped.
float unitFactor(const GltfFile& file, double v, const std::string& field) {
  return std::clamp(finite(file, v, field), 0.0f, 1.0f);
}

glm::vec3 colorFactor(const GltfFile& file, const std::vector<double>& v, size_t size, const std::string& field) {
  if (v.size() != size) file.fail(field + ": must have " + std::to_string(size) + " components");
  return {unitFactor(file, v[0], field), unitFactor(file, v[1], field), unitFactor(file, v[2], field)};
}

bool oneOf(int v, std::initializer_list<int> allowed) {
  return std::find(allowed.begin(), allowed.end(), v) != allowed.end();
}

// KHR_texture_transform: uv' = T(offset) R(rotation) S(scale) (u, v, 1), R turning the UVs counter-clockwise as
// seen with v down the image, as glTF issue #1563 corrects the specification's GLSL listing (and Blender exports).
glm::mat3x2 uvTransformMatrix(glm::vec2 offset, float rotation, glm::vec2 scale) {
  const float c = std::cos(rotation), s = std::sin(rotation);
  // Columns: the images of u, of v and of the origin.
  return {glm::vec2(c, -s) * scale.x, glm::vec2(s, c) * scale.y, offset};
}

struct UvTransform {
  glm::mat3x2 matrix{1.0f};
  std::optional<int> texCoord;  // replaces the textureInfo's
};

// The KHR_texture_transform among a textureInfo's `extensions`, whose types and lengths checkGltfJson has checked.
UvTransform textureTransform(const GltfFile& file, const tinygltf::ExtensionMap& extensions, const std::string& field) {
  UvTransform t;
  const auto it = extensions.find("KHR_texture_transform");
  if (it == extensions.end()) return t;
  const std::string name = field + ".extensions.KHR_texture_transform";
  const tinygltf::Value& v = it->second;
  const auto pair = [&](const char* key, glm::vec2 absent) {
    if (!v.Has(key)) return absent;
    const std::string where = name + "." + key;
    const tinygltf::Value& xy = v.Get(key);
    return glm::vec2(finite(file, xy.Get(0).GetNumberAsDouble(), where + "[0]"),
                     finite(file, xy.Get(1).GetNumberAsDouble(), where + "[1]"));
  };
  const float rotation =
      v.Has("rotation") ? finite(file, v.Get("rotation").GetNumberAsDouble(), name + ".rotation") : 0.0f;
  t.matrix = uvTransformMatrix(pair("offset", glm::vec2(0.0f)), rotation, pair("scale", glm::vec2(1.0f)));
  if (v.Has("texCoord")) t.texCoord = v.Get("texCoord").GetNumberAsInt();
  return t;
}

}  // namespace

MaterialMap GltfMaterials::extensionMap(const tinygltf::Value& extension, const char* key, bool srgb,
                                        const std::string& owner) {
  MaterialMap map;
  if (!extension.Has(key)) return map;
  // checkGltfJson has checked the textureInfo's types: an index within the textures, integer UV sets, a transform.
  const std::string where = owner + "." + key;
  const tinygltf::Value& info = extension.Get(key);
  tinygltf::ExtensionMap extensions;
  if (info.Has("extensions")) {
    const tinygltf::Value& e = info.Get("extensions");
    for (const std::string& name : e.Keys()) extensions[name] = e.Get(name);
  }
  const UvTransform t = textureTransform(file_, extensions, where);
  const int declared = info.Has("texCoord") ? info.Get("texCoord").GetNumberAsInt() : 0;
  map.texCoord = t.texCoord.value_or(declared);
  if (map.texCoord > 1) {
    file_.warn((t.texCoord ? where + ".extensions.KHR_texture_transform" : where) + ": texCoord " +
               std::to_string(map.texCoord) + " is not drawn (TEXCOORD_0 and TEXCOORD_1 are), TEXCOORD_0 is used");
    map.texCoord = 0;
  }
  map.uvTransform = t.matrix;
  map.texture = texture(info.Get("index").GetNumberAsInt(), srgb, where);
  return map;
}

const Material& GltfMaterials::get(int index, const std::string& field) {
  auto it = loaded_.materials.find(index);
  if (it == loaded_.materials.end()) it = loaded_.materials.emplace(index, convert(index, field)).first;
  return it->second;
}

Material GltfMaterials::convert(int index, const std::string& field) {
  // glTF's default material: white, fully metallic and rough.
  Material m;
  m.baseColor = glm::vec3(1.0f);
  m.metalness = 1.0f;
  m.roughness = 1.0f;
  if (index < 0) return m;
  if (static_cast<size_t>(index) >= file_.model.materials.size()) {
    file_.fail(field + ": no material " + std::to_string(index) + " (the file has " +
               std::to_string(file_.model.materials.size()) + ")");
  }
  const tinygltf::Material& g = file_.model.materials[static_cast<size_t>(index)];
  const std::string name = gltfElement("materials", index);
  const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;

  m.baseColor = colorFactor(file_, pbr.baseColorFactor, 4, name + ".pbrMetallicRoughness.baseColorFactor");
  m.alpha = unitFactor(file_, pbr.baseColorFactor[3], name + ".pbrMetallicRoughness.baseColorFactor");
  m.metalness = unitFactor(file_, pbr.metallicFactor, name + ".pbrMetallicRoughness.metallicFactor");
  m.roughness = unitFactor(file_, pbr.roughnessFactor, name + ".pbrMetallicRoughness.roughnessFactor");
  // A textureInfo's texture, and its KHR_texture_transform into `uv`.
  // A textureInfo's texture, its KHR_texture_transform into `uv` and its UV set into `set`.
  const auto map = [&](const auto& info, bool srgb, const std::string& where, glm::mat3x2& uv, int& set) {
    if (info.index < 0) return -1;
    const UvTransform t = textureTransform(file_, info.extensions, where);
    set = t.texCoord.value_or(info.texCoord);
    if (set > 1) {
      file_.warn((t.texCoord ? where + ".extensions.KHR_texture_transform" : where) + ": texCoord " +
                 std::to_string(set) + " is not drawn (TEXCOORD_0 and TEXCOORD_1 are), TEXCOORD_0 is used");
      set = 0;
    }
    uv = t.matrix;
    return texture(info.index, srgb, where);
  };
  m.baseColorTexture = map(pbr.baseColorTexture, true, name + ".pbrMetallicRoughness.baseColorTexture",
                           m.baseColorUvTransform, m.baseColorTexCoord);
  m.metallicRoughnessTexture = map(pbr.metallicRoughnessTexture, false,
                                   name + ".pbrMetallicRoughness.metallicRoughnessTexture",
                                   m.metallicRoughnessUvTransform, m.metallicRoughnessTexCoord);
  m.normalTexture = map(g.normalTexture, false, name + ".normalTexture", m.normalUvTransform, m.normalTexCoord);
  m.normalScale = finite(file_, g.normalTexture.scale, name + ".normalTexture.scale");
  m.occlusionTexture =
      map(g.occlusionTexture, false, name + ".occlusionTexture", m.occlusionUvTransform, m.occlusionTexCoord);
  m.occlusionStrength = unitFactor(file_, g.occlusionTexture.strength, name + ".occlusionTexture.strength");
  m.emissiveTexture =
      map(g.emissiveTexture, true, name + ".emissiveTexture", m.emissiveUvTransform, m.emissiveTexCoord);
  m.emissive = colorFactor(file_, g.emissiveFactor, 3, name + ".emissiveFactor");
  const auto strength = g.extensions.find("KHR_materials_emissive_strength");
  if (strength != g.extensions.end() && strength->second.Has("emissiveStrength")) {
    const std::string where = name + ".extensions.KHR_materials_emissive_strength.emissiveStrength";
    const tinygltf::Value& v = strength->second.Get("emissiveStrength");
    if (!v.IsNumber() || !(v.GetNumberAsDouble() >= 0.0)) file_.fail(where + ": must be a number >= 0");
    m.emissive *= finite(file_, v.GetNumberAsDouble(), where);
    if (!std::isfinite(m.emissive.x + m.emissive.y + m.emissive.z)) file_.fail(where + ": too large");
  }

  if (!readSpecularGlossiness(g, name, m)) readSpecular(g, name, m);
  readClearcoat(g, name, m);
  readSheen(g, name, m);
  readTransmission(g, name, m);

  if (g.alphaMode == "MASK") {
    m.alphaMode = AlphaMode::Mask;
  } else if (g.alphaMode == "BLEND") {
    m.alphaMode = AlphaMode::Blend;
  } else if (g.alphaMode != "OPAQUE") {
    file_.fail(name + ".alphaMode: '" + g.alphaMode + "' is not OPAQUE, MASK or BLEND");
  }
  m.alphaCutoff = finite(file_, g.alphaCutoff, name + ".alphaCutoff");
  if (m.alphaCutoff < 0.0f) file_.fail(name + ".alphaCutoff: must be >= 0");
  m.doubleSided = g.doubleSided;
  m.unlit = g.extensions.count("KHR_materials_unlit") > 0;
  return m;
}

void GltfMaterials::readSpecular(const tinygltf::Material& g, const std::string& name, Material& m) {
  if (const auto ior = g.extensions.find("KHR_materials_ior"); ior != g.extensions.end() && ior->second.Has("ior")) {
    const std::string where = name + ".extensions.KHR_materials_ior.ior";
    m.ior = number(file_, ior->second.Get("ior"), where);
    if (m.ior != 0.0f && !(m.ior >= 1.0f)) file_.fail(where + ": must be 0 or at least 1");
  }
  const auto specular = g.extensions.find("KHR_materials_specular");
  if (specular == g.extensions.end()) return;
  const tinygltf::Value& s = specular->second;
  const std::string where = name + ".extensions.KHR_materials_specular";
  if (s.Has("specularFactor")) {
    m.specular = std::clamp(number(file_, s.Get("specularFactor"), where + ".specularFactor"), 0.0f, 1.0f);
  }
  if (s.Has("specularColorFactor")) {
    const tinygltf::Value& c = s.Get("specularColorFactor");
    if (!c.IsArray() || c.ArrayLen() != 3) file_.fail(where + ".specularColorFactor: must have 3 components");
    for (int i = 0; i < 3; ++i) {
      // Not a unit factor: the colour may exceed 1, the product with F0 being clamped (dielectricSpecular).
      m.specularColor[i] = number(file_, c.Get(i), where + ".specularColorFactor");
      if (m.specularColor[i] < 0.0f) file_.fail(where + ".specularColorFactor: must not be negative");
    }
  }
  m.specularMap = extensionMap(s, "specularTexture", false, where);
  m.specularColorMap = extensionMap(s, "specularColorTexture", true, where);
}

void GltfMaterials::readClearcoat(const tinygltf::Material& g, const std::string& name, Material& m) {
  const auto found = g.extensions.find("KHR_materials_clearcoat");
  if (found == g.extensions.end()) return;
  const tinygltf::Value& v = found->second;
  const std::string where = name + ".extensions.KHR_materials_clearcoat";
  const auto factor = [&](const char* key) {
    if (!v.Has(key)) return 0.0f;
    const tinygltf::Value& x = v.Get(key);
    if (!x.IsNumber()) file_.fail(where + "." + key + ": must be a number");
    return unitFactor(file_, x.GetNumberAsDouble(), where + "." + key);
  };
  m.clearcoat = factor("clearcoatFactor");
  m.clearcoatRoughness = factor("clearcoatRoughnessFactor");
  m.clearcoatMap = extensionMap(v, "clearcoatTexture", false, where);
  m.clearcoatRoughnessMap = extensionMap(v, "clearcoatRoughnessTexture", false, where);
  m.clearcoatNormalMap = extensionMap(v, "clearcoatNormalTexture", false, where);
  if (v.Has("clearcoatNormalTexture") && v.Get("clearcoatNormalTexture").Has("scale")) {
    const std::string scale = where + ".clearcoatNormalTexture.scale";
    m.clearcoatNormalScale = finite(file_, v.Get("clearcoatNormalTexture").Get("scale").GetNumberAsDouble(), scale);
  }
}

void GltfMaterials::readSheen(const tinygltf::Material& g, const std::string& name, Material& m) {
  const auto found = g.extensions.find("KHR_materials_sheen");
  if (found == g.extensions.end()) return;
  const tinygltf::Value& v = found->second;
  const std::string where = name + ".extensions.KHR_materials_sheen";
  if (v.Has("sheenColorFactor")) {
    const tinygltf::Value& c = v.Get("sheenColorFactor");
    if (!c.IsArray() || c.ArrayLen() != 3) file_.fail(where + ".sheenColorFactor: must have 3 components");
    for (int i = 0; i < 3; ++i) {
      if (!c.Get(i).IsNumber()) file_.fail(where + ".sheenColorFactor: must hold numbers");
      m.sheenColor[i] = unitFactor(file_, c.Get(i).GetNumberAsDouble(), where + ".sheenColorFactor");
    }
  }
  if (v.Has("sheenRoughnessFactor")) {
    const tinygltf::Value& r = v.Get("sheenRoughnessFactor");
    if (!r.IsNumber()) file_.fail(where + ".sheenRoughnessFactor: must be a number");
    m.sheenRoughness = unitFactor(file_, r.GetNumberAsDouble(), where + ".sheenRoughnessFactor");
  }
  m.sheenColorMap = extensionMap(v, "sheenColorTexture", true, where);
  m.sheenRoughnessMap = extensionMap(v, "sheenRoughnessTexture", false, where);
}

void GltfMaterials::readTransmission(const tinygltf::Material& g, const std::string& name, Material& m) {
  if (const auto found = g.extensions.find("KHR_materials_transmission"); found != g.extensions.end()) {
    const tinygltf::Value& v = found->second;
    const std::string where = name + ".extensions.KHR_materials_transmission";
    if (v.Has("transmissionFactor")) {
      m.transmission = unitFactor(file_, number(file_, v.Get("transmissionFactor"), where + ".transmissionFactor"),
                                  where + ".transmissionFactor");
    }
    m.transmissionMap = extensionMap(v, "transmissionTexture", false, where);
  }
  const auto found = g.extensions.find("KHR_materials_volume");
  if (found == g.extensions.end()) return;
  const tinygltf::Value& v = found->second;
  const std::string where = name + ".extensions.KHR_materials_volume";
  if (v.Has("thicknessFactor")) {
    m.thickness = number(file_, v.Get("thicknessFactor"), where + ".thicknessFactor");
    if (!(m.thickness >= 0.0f)) file_.fail(where + ".thicknessFactor: must be >= 0");
  }
  if (v.Has("attenuationDistance")) {
    m.attenuationDistance = number(file_, v.Get("attenuationDistance"), where + ".attenuationDistance");
    if (!(m.attenuationDistance > 0.0f)) file_.fail(where + ".attenuationDistance: must be > 0");
  }
  if (v.Has("attenuationColor")) {
    const tinygltf::Value& c = v.Get("attenuationColor");
    if (!c.IsArray() || c.ArrayLen() != 3) file_.fail(where + ".attenuationColor: must have 3 components");
    for (int i = 0; i < 3; ++i) {
      m.attenuationColor[i] = unitFactor(file_, number(file_, c.Get(i), where + ".attenuationColor"),
                                         where + ".attenuationColor");
    }
  }
  m.thicknessMap = extensionMap(v, "thicknessTexture", false, where);
}

// KHR_materials_specular's specification converts a specular-glossiness material so: a dielectric of ior 0 (F0 1)
// whose specular colour is the specular factor, F90 1, the diffuse factor and texture as base colour, metalness 0
// and roughness 1 - glossiness; the glossiness in the specular-glossiness map's alpha becomes a roughness map here,
// and its colour the specular colour map.
bool GltfMaterials::readSpecularGlossiness(const tinygltf::Material& g, const std::string& name, Material& m) {
  const auto found = g.extensions.find("KHR_materials_pbrSpecularGlossiness");
  if (found == g.extensions.end()) return false;
  const tinygltf::Value& v = found->second;
  const std::string where = name + ".extensions.KHR_materials_pbrSpecularGlossiness";
  const auto unit = [&](const tinygltf::Value& x, const std::string& field) {
    return unitFactor(file_, number(file_, x, field), field);
  };
  const auto factors = [&](const char* key, std::vector<double> fallback) {
    if (!v.Has(key)) return fallback;
    const tinygltf::Value& a = v.Get(key);
    if (!a.IsArray() || a.ArrayLen() != fallback.size()) {
      file_.fail(where + "." + key + ": must have " + std::to_string(fallback.size()) + " components");
    }
    for (size_t i = 0; i < fallback.size(); ++i) fallback[i] = unit(a.Get(int(i)), where + "." + key);
    return fallback;
  };
  const std::vector<double> diffuse = factors("diffuseFactor", {1.0, 1.0, 1.0, 1.0});
  const std::vector<double> specular = factors("specularFactor", {1.0, 1.0, 1.0});
  const float glossiness = v.Has("glossinessFactor") ? unit(v.Get("glossinessFactor"), where + ".glossinessFactor")
                                                     : 1.0f;
  m.baseColor = glm::vec3(float(diffuse[0]), float(diffuse[1]), float(diffuse[2]));
  m.alpha = float(diffuse[3]);
  m.metalness = 0.0f;
  m.metallicRoughnessTexture = -1;
  m.roughness = 1.0f - glossiness;
  m.ior = 0.0f;
  m.specular = 1.0f;
  m.specularColor = glm::vec3(float(specular[0]), float(specular[1]), float(specular[2]));
  // A textureInfo as the core material's maps read one: its index, texCoord and KHR_texture_transform.
  const MaterialMap diffuseMap = extensionMap(v, "diffuseTexture", true, where);
  m.baseColorTexture = diffuseMap.texture;
  m.baseColorUvTransform = diffuseMap.uvTransform;
  m.baseColorTexCoord = diffuseMap.texCoord;
  const size_t decodedBefore = loaded_.textures.size();
  const MaterialMap glossinessMap = extensionMap(v, "specularGlossinessTexture", false, where);
  const int glossMap = glossinessMap.texture;
  m.metallicRoughnessUvTransform = glossinessMap.uvTransform;
  m.metallicRoughnessTexCoord = glossinessMap.texCoord;
  if (glossMap >= 0) {
    // Roughness 1 - glossinessFactor x alpha in the green channel, as a metallic-roughness map holds it; the
    // factor is folded in, the material's roughness factor becomes 1 and its metalness stays 0. A map decoded for
    // this material alone is rewritten in place (and forgotten by the cache), so that no unused copy is uploaded.
    const bool decodedHere = loaded_.textures.size() != decodedBefore;
    TextureData roughness = scene_.textures[size_t(glossMap)];
    roughness.name += " (roughness from glossiness)";
    for (size_t i = 0; i < roughness.rgba.size(); i += 4) {
      const float gloss = glossiness * float(roughness.rgba[i + 3]) / 255.0f;
      roughness.rgba[i + 0] = 0;
      roughness.rgba[i + 1] = uint8_t(std::lround((1.0f - gloss) * 255.0f));
      roughness.rgba[i + 2] = 0;
      roughness.rgba[i + 3] = 255;
    }
    if (decodedHere) {
      loaded_.textures.erase({v.Get("specularGlossinessTexture").Get("index").GetNumberAsInt(), false});
      scene_.textures[size_t(glossMap)] = std::move(roughness);
      m.metallicRoughnessTexture = glossMap;
    } else {
      scene_.textures.push_back(std::move(roughness));
      m.metallicRoughnessTexture = int(scene_.textures.size()) - 1;
    }
    m.roughness = 1.0f;
    // Its colour (sRGB) times the specular factor is the specular colour, as KHR_materials_specular's map.
    m.specularColorMap = extensionMap(v, "specularGlossinessTexture", true, where);
  }
  return true;
}

int GltfMaterials::texture(int index, bool srgb, const std::string& field) {
  const auto cached = loaded_.textures.find({index, srgb});
  if (cached != loaded_.textures.end()) return cached->second;
  const tinygltf::Model& model = file_.model;
  if (static_cast<size_t>(index) >= model.textures.size()) {
    file_.fail(field + ": no texture " + std::to_string(index) + " (the file has " +
               std::to_string(model.textures.size()) + ")");
  }
  const tinygltf::Texture& t = model.textures[static_cast<size_t>(index)];
  const std::string name = gltfElement("textures", index);
  // EXT_texture_webp names the WebP image to use instead of `source`, its fallback (which may be absent).
  int source = t.source;
  std::string sourceField = name + ".source";
  const auto webp = t.extensions.find("EXT_texture_webp");
  if (webp != t.extensions.end()) {
    sourceField = name + ".extensions.EXT_texture_webp.source";
    const tinygltf::Value& v = webp->second.Get("source");
    if (!v.IsInt()) file_.fail(sourceField + ": must be an image index");
    source = v.GetNumberAsInt();
  }
  if (source < 0 || static_cast<size_t>(source) >= model.images.size()) {
    file_.fail(sourceField + ": no image " + std::to_string(source) +
               " (a texture needs a PNG, JPEG or, with EXT_texture_webp, WebP source)");
  }
  TextureData data;
  if (t.sampler >= 0) {
    if (static_cast<size_t>(t.sampler) >= model.samplers.size()) {
      file_.fail(name + ".sampler: no sampler " + std::to_string(t.sampler));
    }
    const tinygltf::Sampler& s = model.samplers[static_cast<size_t>(t.sampler)];
    const std::string sampler = gltfElement("samplers", t.sampler);
    const std::initializer_list<int> wraps = {TINYGLTF_TEXTURE_WRAP_REPEAT, TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE,
                                              TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT};
    if (!oneOf(s.wrapS, wraps)) file_.fail(sampler + ".wrapS: unknown wrap mode " + std::to_string(s.wrapS));
    if (!oneOf(s.wrapT, wraps)) file_.fail(sampler + ".wrapT: unknown wrap mode " + std::to_string(s.wrapT));
    if (!oneOf(s.minFilter,
               {-1, TINYGLTF_TEXTURE_FILTER_NEAREST, TINYGLTF_TEXTURE_FILTER_LINEAR,
                TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST, TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST,
                TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR, TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR})) {
      file_.fail(sampler + ".minFilter: unknown filter " + std::to_string(s.minFilter));
    }
    if (!oneOf(s.magFilter, {-1, TINYGLTF_TEXTURE_FILTER_NEAREST, TINYGLTF_TEXTURE_FILTER_LINEAR})) {
      file_.fail(sampler + ".magFilter: unknown filter " + std::to_string(s.magFilter));
    }
    // glTF sampler values are the GL enums; undefined filters keep TextureData's trilinear default.
    data.wrapS = s.wrapS;
    data.wrapT = s.wrapT;
    if (s.minFilter >= 0) data.minFilter = s.minFilter;
    if (s.magFilter >= 0) data.magFilter = s.magFilter;
  }
  std::string problem;
  if (!readImage(source, data, problem)) {
    // As viewers draw it: without the texture, which for every role is its neutral value (white base colour,
    // metal-roughness, occlusion and emission factors alone, the interpolated normal).
    if (file_.policy.strict) file_.fail(problem);
    file_.warn(problem + ": drawn without it, as if white (a flat normal map); --strict refuses");
    loaded_.textures.emplace(std::make_pair(index, srgb), -1);
    return -1;
  }
  data.srgb = srgb;
  scene_.textures.push_back(std::move(data));
  const int added = static_cast<int>(scene_.textures.size()) - 1;
  loaded_.textures.emplace(std::make_pair(index, srgb), added);
  return added;
}

bool GltfMaterials::readImage(int index, TextureData& data, std::string& problem) const {
  const tinygltf::Image& image = file_.model.images[static_cast<size_t>(index)];
  const std::string label = gltfElement("images", index) + (!image.uri.empty()    ? " (" + quoteUri(image.uri) + ")"
                                                            : !image.name.empty() ? " (" + quoteUri(image.name) + ")"
                                                                                  : "");
  ByteSpan bytes{nullptr, 0};
  if (image.bufferView >= 0) {
    bytes = bufferViewBytes(file_, image.bufferView, gltfElement("images", index) + ".bufferView");
  } else {
    const std::vector<unsigned char>& encoded = file_.encodedImages[static_cast<size_t>(index)];
    if (encoded.empty()) {
      // checkGltfJson placed the URI; the file is missing, or unreadable (a folder, too large, no permission).
      std::error_code error;
      const bool exists =
          std::filesystem::exists(placeGltfUri(image.uri, std::filesystem::path(file_.path).parent_path(),
                                               file_.policy), error);
      problem = label + ": " + (exists ? "cannot read the image file" : "no such file");
      return false;
    }
    bytes = {encoded.data(), encoded.size()};
  }
  // Decoded by what the bytes are, as browsers decode them; a mimeType that says otherwise is named.
  const char* actual = imageMimeType(bytes.data, bytes.size);
  const std::string& declared = file_.imageMimeTypes[static_cast<size_t>(index)];
  if (actual && !declared.empty() && declared != actual) {
    const std::string what = gltfElement("images", index) + ".mimeType: \"" + declared + "\", but the bytes are " +
                             actual;
    if (file_.policy.strict) file_.fail(what);
    file_.warn(what + ", decoded as such (--strict refuses it)");
  }
  ImageRgba8 pixels;
  try {
    pixels = pbr::decodeImage(bytes.data, bytes.size, label);
  } catch (const std::runtime_error& e) {
    problem = e.what();
    return false;
  }
  data.name = image.uri.empty() || isDataUri(image.uri) ? label : image.uri;
  data.width = pixels.width;
  data.height = pixels.height;
  data.rgba = std::move(pixels.pixels);
  return true;
}

}  // namespace pbr
