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
