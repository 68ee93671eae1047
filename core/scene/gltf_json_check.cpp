#include "core/scene/gltf_json_check.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/scene/gltf_uri.hpp"
#include "core/scene/input_file.hpp"
#include "core/scene/json_text.hpp"
#include "core/scene/messages.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

bool isMeshoptFallback(const nlohmann::json& buffer) {
  if (!buffer.is_object()) return false;
  const auto extensions = buffer.find("extensions");
  if (extensions == buffer.end() || !extensions->is_object()) return false;
  const auto meshopt = extensions->find("EXT_meshopt_compression");
  if (meshopt == extensions->end() || !meshopt->is_object()) return false;
  const auto fallback = meshopt->find("fallback");
  return fallback != meshopt->end() && fallback->is_boolean() && fallback->get<bool>();
}

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr uint64_t kMaxIndex = INT_MAX;        // tinygltf keeps indices as int
constexpr uint64_t kMaxBytes = kMaxInputBytes;  // no buffer is larger than the largest file read

uint64_t componentSize(uint64_t componentType) {
  switch (componentType) {
    case 5120:  // BYTE
    case 5121:  // UNSIGNED_BYTE
      return 1;
    case 5122:  // SHORT
    case 5123:  // UNSIGNED_SHORT
      return 2;
    case 5125:  // UNSIGNED_INT
    case 5126:  // FLOAT
      return 4;
    default:
      return 0;
  }
}

uint64_t componentsOf(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4" || type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  if (type == "MAT4") return 16;
  return 0;
}

std::string item(const std::string& array, std::size_t index) { return array + "[" + std::to_string(index) + "]"; }

class Checker {
 public:
  Checker(const json& doc, const GltfJsonContext& context) : doc_(doc), context_(context) {}

  void run() {
    if (!doc_.is_object()) fail("top level", "must be a JSON object (got " + quoteJson(doc_) + ")");
    // What the specification requires and tinygltf refuses in its own words, naming no path: named here first.
    if (!doc_.contains("asset")) fail("asset", "is required (an object with the glTF version)");
    checkBuffers();
    checkBufferViews();
    checkAccessors();
    checkImagesTexturesSamplers();
    checkMaterials();
    checkMeshes();
    checkNodes();
    checkLights();
    checkCameras();
    const std::vector<const json*> scenes = objects(doc_, "scenes", "scenes");
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      const json* scene = scenes[i];
      indexArray(*scene, "nodes", item("scenes", i), "nodes");
    }
    index(doc_, "scene", "", "scenes");
    const std::vector<const json*> skins = objects(doc_, "skins", "skins");
    for (std::size_t i = 0; i < skins.size(); ++i) {
      const std::string field = item("skins", i);
      if (!skins[i]->contains("joints")) fail(field + ".joints", "is required (the skin's joint nodes)");
      indexArray(*skins[i], "joints", field, "nodes");
      index(*skins[i], "skeleton", field, "nodes");
      index(*skins[i], "inverseBindMatrices", field, "accessors");
    }
    const std::vector<const json*> animations = objects(doc_, "animations", "animations");
    for (std::size_t i = 0; i < animations.size(); ++i) checkAnimation(*animations[i], item("animations", i));
  }

  void checkAnimation(const json& animation, const std::string& field) const {
    const std::vector<const json*> samplers = objects(animation, "samplers", field + ".samplers");
    for (std::size_t s = 0; s < samplers.size(); ++s) {
      const std::string name = field + "." + item("samplers", s);
      index(*samplers[s], "input", name, "accessors", true);
      index(*samplers[s], "output", name, "accessors", true);
    }
    const std::vector<const json*> channels = objects(animation, "channels", field + ".channels");
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const std::string name = field + "." + item("channels", c);
      const uint64_t s = *integer(*channels[c], "sampler", name, kMaxIndex, true);
      if (s >= samplers.size()) fail(name + ".sampler", "no sampler " + std::to_string(s) + " in " + field);
      if (channels[c]->contains("target")) {
        index(member(*channels[c], "target", name), "node", name + ".target", "nodes");
      }
    }
  }

 private:
  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw SceneError(context_.path + ": " + field + ": " + what);
  }

  static std::string join(const std::string& owner, const char* key) {
    return owner.empty() ? key : owner + "." + key;
  }

  std::size_t count(const char* array) const {
    const auto it = doc_.find(array);
    return it != doc_.end() && it->is_array() ? it->size() : 0;
  }

  const json& member(const json& object, const char* key, const std::string& owner) const {
    const json& v = object.at(key);
    if (!v.is_object()) fail(join(owner, key), "must be an object (got " + quoteJson(v) + ")");
    return v;
  }

  // The elements of array `key` of `object` (none when absent), each checked to be an object.
  std::vector<const json*> objects(const json& object, const char* key, const std::string& field) const {
    std::vector<const json*> out;
    const auto it = object.find(key);
    if (it == object.end()) return out;
    if (!it->is_array()) fail(field, "must be an array (got " + quoteJson(*it) + ")");
    for (std::size_t i = 0; i < it->size(); ++i) {
      if (!(*it)[i].is_object()) fail(item(field, i), "must be an object (got " + quoteJson((*it)[i]) + ")");
      out.push_back(&(*it)[i]);
    }
    return out;
  }

  // A non-negative integer in [lo, max]: 4.0, 4.5, -4 and "4" are refused alike.
  std::optional<uint64_t> integer(const json& object, const char* key, const std::string& owner, uint64_t max,
                                  bool required = false, uint64_t lo = 0) const {
    const std::string field = join(owner, key);
    const auto it = object.find(key);
    if (it == object.end()) {
      if (required) fail(field, "missing (a required integer)");
      return std::nullopt;
    }
    if (!it->is_number_unsigned()) fail(field, "must be a non-negative integer (got " + quoteJson(*it) + ")");
    const uint64_t v = it->get<uint64_t>();
    if (v < lo || v > max) {
      fail(field, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(max) + "] (got " +
                      std::to_string(v) + ")");
    }
    return v;
  }

  // An index into top-level array `target`.
  std::optional<uint64_t> index(const json& object, const char* key, const std::string& owner, const char* target,
                                bool required = false) const {
    const std::optional<uint64_t> v = integer(object, key, owner, kMaxIndex, required);
    if (v && *v >= count(target)) {
      fail(join(owner, key),
           "no " + std::string(target) + "[" + std::to_string(*v) + "] (the file has " + std::to_string(count(target)) + ")");
    }
    return v;
  }

  void indexArray(const json& object, const char* key, const std::string& owner, const char* target) const {
    const auto it = object.find(key);
    if (it == object.end()) return;
    const std::string field = join(owner, key);
    if (!it->is_array()) fail(field, "must be an array of indices (got " + quoteJson(*it) + ")");
    for (std::size_t i = 0; i < it->size(); ++i) {
      const json wrapped = {{"i", (*it)[i]}};
      try {
        index(wrapped, "i", "", target);
      } catch (const SceneError& e) {
        // Renamed from the wrapper's "i" to the element's own path.
        const std::string what = e.what(), prefix = context_.path + ": i: ";
        fail(item(field, i), what.substr(prefix.size()));
      }
    }
  }

  void numbers(const json& object, const char* key, const std::string& owner, std::size_t size) const {
    const auto it = object.find(key);
    if (it == object.end()) return;
    bool ok = it->is_array() && it->size() == size;
    for (std::size_t i = 0; ok && i < size; ++i) ok = (*it)[i].is_number();
    if (!ok) fail(join(owner, key), "must be an array of " + std::to_string(size) + " numbers (got " + quoteJson(*it) + ")");
  }

  // Number `key` of an extension, or with `size` an array of that many. tinygltf keeps an extension's integer
  // literal as an int, so one beyond 32 bits, which it would wrap, is refused rather than misread.
  void extensionNumbers(const json& object, const char* key, const std::string& owner, std::size_t size = 0) const {
    const auto it = object.find(key);
    if (it == object.end()) return;
    const std::string field = join(owner, key);
    if (size > 0 && !(it->is_array() && it->size() == size)) {
      fail(field, "must be an array of " + std::to_string(size) + " numbers (got " + quoteJson(*it) + ")");
    }
    for (std::size_t i = 0; i < std::max<std::size_t>(size, 1); ++i) {
      const json& v = size > 0 ? (*it)[i] : *it;
      const std::string at = size > 0 ? item(field, i) : field;
      if (!v.is_number()) fail(at, "must be a number (got " + quoteJson(v) + ")");
      if (v.is_number_float()) continue;
      const bool fits = v.is_number_unsigned() ? v.get<uint64_t>() <= INT_MAX
                                               : v.get<int64_t>() >= INT_MIN && v.get<int64_t>() <= INT_MAX;
      if (!fits) {
        fail(at, "an integer beyond 32 bits would be misread; write it with an exponent (got " + quoteJson(v) + ")");
      }
    }
  }

  void checkBuffers() {
    const std::vector<const json*> buffers = objects(doc_, "buffers", "buffers");
    for (std::size_t i = 0; i < buffers.size(); ++i) {
      const json* buffer = buffers[i];
      const std::string field = item("buffers", i);
      const uint64_t length = *integer(*buffer, "byteLength", field, kMaxBytes, true, 1);
      bufferLengths_.push_back(length);
      const auto uri = buffer->find("uri");
      if (uri == buffer->end() && isMeshoptFallback(*buffer)) continue;  // its views are decoded from others
      if (uri == buffer->end()) {
        if (i != 0 || !context_.binChunk) fail(field + ".uri", "missing (only a GLB's first buffer may omit it)");
        if (length > *context_.binChunk || *context_.binChunk - length > 3) {
          fail(field + ".byteLength", std::to_string(length) + ", but the GLB BIN chunk holds " +
                                          std::to_string(*context_.binChunk) + " bytes");
        }
      } else {
        if (!uri->is_string()) fail(field + ".uri", "must be a string (got " + quoteJson(*uri) + ")");
        const std::string& text = uri->get_ref<const std::string&>();
        std::uint64_t held = 0;
        try {
          held = isDataUri(text) ? dataUriSize(text) : fs::file_size(resolveGltfUri(text, context_.folder, context_.policy));
        } catch (const std::runtime_error& e) {
          fail(field + ".uri", e.what());
        }
        if (held != length) {
          fail(field + ".byteLength", std::to_string(length) + ", but " + quoteUri(text) + " holds " +
                                          std::to_string(held) + " bytes");
        }
      }
    }
  }

  void checkBufferViews() {
    const std::vector<const json*> views = objects(doc_, "bufferViews", "bufferViews");
    for (std::size_t i = 0; i < views.size(); ++i) {
      const json* view = views[i];
      const std::string field = item("bufferViews", i);
      const uint64_t buffer = *index(*view, "buffer", field, "buffers", true);
      const uint64_t offset = integer(*view, "byteOffset", field, kMaxBytes).value_or(0);
      const uint64_t length = *integer(*view, "byteLength", field, kMaxBytes, true, 1);
      const std::optional<uint64_t> stride = integer(*view, "byteStride", field, 252, false, 0);
      if (stride && *stride == 0 && !context_.policy.strict) {
        // The schema's minimum is 4, but Unity's exporter writes 0 and tinygltf, three.js, Blender and
        // glTF-Sample-Viewer read it as tightly packed, as an absent stride is read.
        warnOnce(context_.path + ": " + field + ".byteStride: 0 read as tightly packed (the specification asks for "
                 "4 to 252 or no byteStride; --strict refuses it)");
      } else if (stride && *stride < 4) {
        fail(field + ".byteStride", "must be an integer in [4, 252] (got " + std::to_string(*stride) + ")");
      }
      if (stride && *stride % 4 != 0) {
        fail(field + ".byteStride", "must be a multiple of 4 (got " + std::to_string(*stride) + ")");
      }
      integer(*view, "target", field, 34963, false, 34962);  // ARRAY_BUFFER or ELEMENT_ARRAY_BUFFER
      if (offset + length > bufferLengths_[buffer]) {
        fail(field, "byteOffset " + std::to_string(offset) + " + byteLength " + std::to_string(length) +
                        " run past the end of buffers[" + std::to_string(buffer) + "] (" +
                        std::to_string(bufferLengths_[buffer]) + " bytes)");
      }
      views_.push_back({offset, length, stride.value_or(0)});
    }
  }

  void checkAccessors() {
    const std::vector<const json*> accessors = objects(doc_, "accessors", "accessors");
    for (std::size_t i = 0; i < accessors.size(); ++i) {
      const json* accessor = accessors[i];
      const std::string field = item("accessors", i);
      const uint64_t componentType = *integer(*accessor, "componentType", field, 5126, true, 5120);
      const uint64_t size = componentSize(componentType);
      if (size == 0) fail(field + ".componentType", "must be 5120, 5121, 5122, 5123, 5125 or 5126 (got " + std::to_string(componentType) + ")");
      const uint64_t count = *integer(*accessor, "count", field, kMaxBytes, true, 0);
      if (count == 0 && context_.policy.strict) {
        fail(field + ".count", "must be an integer in [1, " + std::to_string(kMaxBytes) + "] (got 0)");
      } else if (count == 0) {
        // The schema's minimum is 1, but exporters (Obj2GltfConverter) leave unused accessors empty, which
        // tinygltf, three.js and glTF-Sample-Viewer read; a primitive reading one has nothing to draw.
        warnOnce(context_.path + ": " + field + ".count: 0 read as an empty accessor (the specification asks for at "
                 "least 1; --strict refuses it)");
      }
      const auto type = accessor->find("type");
      const uint64_t components = type != accessor->end() && type->is_string() ? componentsOf(type->get<std::string>()) : 0;
      if (components == 0) {
        fail(field + ".type", "must be SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4 (got " +
                                  (type == accessor->end() ? std::string("nothing") : quoteJson(*type)) + ")");
      }
      // min and max, as many numbers as the type has components: the loader measures its own bounds, so a pair of
      // another form changes nothing drawn, but viewers that cull by it would.
      for (const char* key : {"min", "max"}) {
        const auto bound = accessor->find(key);
        if (bound == accessor->end()) continue;
        if (bound->is_array() && bound->size() == components &&
            std::all_of(bound->begin(), bound->end(), [](const json& v) { return v.is_number(); })) {
          continue;
        }
        const std::string expected = std::to_string(components) + " number" + (components == 1 ? "" : "s");
        if (context_.policy.strict) fail(field + "." + key, "must be " + expected + " (got " + quoteJson(*bound) + ")");
        warnOnce(context_.path + ": " + field + "." + key + ": " + quoteJson(*bound) + " is not " + expected +
                 ", one per component; not used (--strict refuses it)");
      }
      const std::optional<uint64_t> view = index(*accessor, "bufferView", field, "bufferViews");
      const std::optional<uint64_t> offset = integer(*accessor, "byteOffset", field, kMaxBytes);
      if (offset && *offset % size != 0) {
        fail(field + ".byteOffset", "must be a multiple of " + std::to_string(size) + ", its component size (got " +
                                        std::to_string(*offset) + ")");
      }
      if (view && count > 0) {
        checkAccessorRange(field, views_[*view], *view, offset.value_or(0), size, size * components, count);
      }
      if (accessor->contains("sparse")) checkSparse(member(*accessor, "sparse", field), field + ".sparse");
    }
  }

  struct View {
    uint64_t offset, length, stride;
  };

  void checkAccessorRange(const std::string& field, const View& view, uint64_t viewIndex, uint64_t offset,
                          uint64_t size, uint64_t elementSize, uint64_t count) const {
    const std::string viewName = item("bufferViews", viewIndex);
    if ((view.offset + offset) % size != 0) {
      fail(field + ".byteOffset", viewName + ".byteOffset " + std::to_string(view.offset) + " + " +
                                      std::to_string(offset) + " is not a multiple of the component size " +
                                      std::to_string(size));
    }
    if (offset >= view.length) {
      fail(field + ".byteOffset", std::to_string(offset) + " is past the end of " + viewName + " (" +
                                      std::to_string(view.length) + " bytes)");
    }
    const uint64_t stride = view.stride ? view.stride : elementSize;
    if (stride < elementSize) {
      fail(viewName + ".byteStride", std::to_string(stride) + " is smaller than the " + std::to_string(elementSize) +
                                         "-byte elements of " + field);
    }
    // Both are at most 2^31, so the product cannot overflow.
    if (offset + (count - 1) * stride + elementSize > view.length) {
      fail(field + ".count", std::to_string(count) + " elements of " + std::to_string(elementSize) + " bytes (stride " +
                                 std::to_string(stride) + ") from byteOffset " + std::to_string(offset) +
                                 " run past the end of " + viewName + " (" + std::to_string(view.length) + " bytes)");
    }
  }

  void checkSparse(const json& sparse, const std::string& field) const {
    integer(sparse, "count", field, kMaxBytes, true, 1);
    if (!sparse.contains("indices") || !sparse.contains("values")) fail(field, "must have indices and values");
    const json& indices = member(sparse, "indices", field);
    index(indices, "bufferView", field + ".indices", "bufferViews", true);
    integer(indices, "byteOffset", field + ".indices", kMaxBytes);
    integer(indices, "componentType", field + ".indices", 5125, true, 5121);
    const json& values = member(sparse, "values", field);
    index(values, "bufferView", field + ".values", "bufferViews", true);
    integer(values, "byteOffset", field + ".values", kMaxBytes);
  }

  void checkImagesTexturesSamplers() const {
    const std::vector<const json*> images = objects(doc_, "images", "images");
    for (std::size_t i = 0; i < images.size(); ++i) {
      const json* image = images[i];
      const std::string field = item("images", i);
      index(*image, "bufferView", field, "bufferViews");
      const auto uri = image->find("uri");
      if (uri == image->end() && !image->contains("bufferView")) fail(field, "needs a uri or a bufferView");
      if (uri == image->end()) continue;
      if (!uri->is_string()) fail(field + ".uri", "must be a string (got " + quoteJson(*uri) + ")");
      const std::string& text = uri->get_ref<const std::string&>();
      try {
        // A missing image file is drawn as a placeholder with a warning (GltfMaterials), or refused with --strict.
        if (!isDataUri(text) && context_.policy.strict) resolveGltfUri(text, context_.folder, context_.policy);
        if (!isDataUri(text)) placeGltfUri(text, context_.folder, context_.policy);
      } catch (const std::runtime_error& e) {
        fail(field + ".uri", e.what());
      }
    }
    const std::vector<const json*> textures = objects(doc_, "textures", "textures");
    for (std::size_t i = 0; i < textures.size(); ++i) {
      const json* texture = textures[i];
      const std::string field = item("textures", i);
      index(*texture, "sampler", field, "samplers");
      index(*texture, "source", field, "images");
    }
    const std::vector<const json*> samplers = objects(doc_, "samplers", "samplers");
    for (std::size_t i = 0; i < samplers.size(); ++i) {
      const json* sampler = samplers[i];
      const std::string field = item("samplers", i);
      for (const char* key : {"magFilter", "minFilter", "wrapS", "wrapT"}) integer(*sampler, key, field, 65535);
    }
  }

  void textureInfo(const json& object, const char* key, const std::string& owner) const {
    if (!object.contains(key)) return;
    const std::string field = join(owner, key);
    const json& info = member(object, key, owner);
    index(info, "index", field, "textures", true);
    integer(info, "texCoord", field, kMaxIndex);
    if (!info.contains("extensions")) return;
    const json& extensions = member(info, "extensions", field);
    if (!extensions.contains("KHR_texture_transform")) return;
    // tinygltf would drop a transform that is not an object without a word.
    const json& transform = member(extensions, "KHR_texture_transform", field + ".extensions");
    const std::string name = field + ".extensions.KHR_texture_transform";
    extensionNumbers(transform, "offset", name, 2);
    extensionNumbers(transform, "rotation", name);
    extensionNumbers(transform, "scale", name, 2);
    integer(transform, "texCoord", name, kMaxIndex);
  }

  // Value `key` of `object`, where present, of the JSON type `is` tests (`what` names it for the message).
  void typed(const json& object, const char* key, const std::string& owner, bool (json::*is)() const noexcept,
             const char* what) const {
    const auto it = object.find(key);
    if (it != object.end() && !((*it).*is)()) fail(join(owner, key), std::string("must be ") + what + " (got " +
                                                                           quoteJson(*it) + ")");
  }

  // tinygltf drops a whole material (and with it the mesh's look) without a word when one of its values has the
  // wrong form, so each is checked here by name.
  void checkMaterials() const {
    const std::vector<const json*> materials = objects(doc_, "materials", "materials");
    for (std::size_t i = 0; i < materials.size(); ++i) {
      const json* material = materials[i];
      const std::string field = item("materials", i);
      if (material->contains("pbrMetallicRoughness")) {
        const json& pbr = member(*material, "pbrMetallicRoughness", field);
        const std::string owner = field + ".pbrMetallicRoughness";
        textureInfo(pbr, "baseColorTexture", owner);
        textureInfo(pbr, "metallicRoughnessTexture", owner);
        numbers(pbr, "baseColorFactor", owner, 4);
        for (const char* key : {"metallicFactor", "roughnessFactor"}) {
          typed(pbr, key, owner, &json::is_number, "a number");
        }
      }
      for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"}) {
        textureInfo(*material, key, field);
      }
      if (material->contains("normalTexture")) {
        typed(member(*material, "normalTexture", field), "scale", field + ".normalTexture", &json::is_number,
              "a number");
      }
      if (material->contains("occlusionTexture")) {
        typed(member(*material, "occlusionTexture", field), "strength", field + ".occlusionTexture",
              &json::is_number, "a number");
      }
      // The material extensions' maps, read as the core's are (GltfMaterials::extensionMap).
      if (material->contains("extensions")) {
        const json& extensions = member(*material, "extensions", field);
        const std::pair<const char*, std::vector<const char*>> maps[] = {
            {"KHR_materials_clearcoat", {"clearcoatTexture", "clearcoatRoughnessTexture", "clearcoatNormalTexture"}},
            {"KHR_materials_sheen", {"sheenColorTexture", "sheenRoughnessTexture"}},
            {"KHR_materials_specular", {"specularTexture", "specularColorTexture"}},
            {"KHR_materials_transmission", {"transmissionTexture"}},
            {"KHR_materials_volume", {"thicknessTexture"}},
            {"KHR_materials_pbrSpecularGlossiness", {"diffuseTexture", "specularGlossinessTexture"}}};
        for (const auto& [name, keys] : maps) {
          if (!extensions.contains(name)) continue;
          const std::string owner = field + ".extensions." + name;
          const json& extension = member(extensions, name, field + ".extensions");
          for (const char* key : keys) textureInfo(extension, key, owner);
          if (extension.contains("clearcoatNormalTexture")) {
            typed(member(extension, "clearcoatNormalTexture", owner), "scale", owner + ".clearcoatNormalTexture",
                  &json::is_number, "a number");
          }
        }
      }
      numbers(*material, "emissiveFactor", field, 3);
      typed(*material, "alphaMode", field, &json::is_string, "a string");
      typed(*material, "alphaCutoff", field, &json::is_number, "a number");
      typed(*material, "doubleSided", field, &json::is_boolean, "true or false");
    }
  }

  // KHR_lights_punctual's values of their form: tinygltf reads a string intensity ("NaN") or range as its default
  // without a word. A range of 0, which the specification forbids, is what three.js reads as unbounded, and so is
  // it read here, with a warning.
  void checkLights() const {
    const auto extensions = doc_.find("extensions");
    if (extensions == doc_.end() || !extensions->is_object() || !extensions->contains("KHR_lights_punctual")) return;
    const json& punctual = member(*extensions, "KHR_lights_punctual", "extensions");
    const std::vector<const json*> lights = objects(punctual, "lights", "extensions.KHR_lights_punctual.lights");
    for (std::size_t i = 0; i < lights.size(); ++i) {
      const json& light = *lights[i];
      const std::string field = item("extensions.KHR_lights_punctual.lights", i);
      if (!light.contains("type")) fail(field + ".type", "is required (\"point\", \"spot\" or \"directional\")");
      typed(light, "type", field, &json::is_string, "a string");
      extensionNumbers(light, "color", field, 3);
      extensionNumbers(light, "intensity", field);
      extensionNumbers(light, "range", field);
      // Babylon's exporter writes "spot": null on point lights, read as absent, as tinygltf and the viewers do. A
      // spot light without one, which the specification forbids, gets the default cone, as three.js reads it.
      const bool isSpot = light.contains("type") && light["type"] == "spot";
      if (isSpot && (!light.contains("spot") || light["spot"].is_null())) {
        if (context_.policy.strict) fail(field + ".spot", "is required for a spot light");
        warnOnce(context_.path + ": " + field + ".spot: missing for a spot light: the default cone (inner angle 0, "
                 "outer pi/4) is used, as three.js reads it (--strict refuses it)");
      }
      if (light.contains("spot") && !light["spot"].is_null()) {
        const json& spot = member(light, "spot", field);
        extensionNumbers(spot, "innerConeAngle", field + ".spot");
        extensionNumbers(spot, "outerConeAngle", field + ".spot");
      }
      const auto range = light.find("range");
      if (range != light.end() && *range == 0) {
        if (context_.policy.strict) fail(field + ".range", "must be positive (got 0)");
        warnOnce(context_.path + ": " + field + ".range: 0 read as no range, as three.js reads it (the specification "
                 "asks for a positive number; --strict refuses it)");
      }
    }
  }

  // A camera's values of their form (tinygltf reads a string as the default without a word), an orthographic
  // camera's four all given (the specification requires them; their values are checked at load). The frame's own
  // aspect ratio replaces the file's, so a perspective aspectRatio of 0 or below, which the specification forbids,
  // changes nothing drawn: a warning, --strict refusing it.
  void checkCameras() const {
    const std::vector<const json*> cameras = objects(doc_, "cameras", "cameras");
    for (std::size_t i = 0; i < cameras.size(); ++i) {
      const std::string field = item("cameras", i);
      if (!cameras[i]->contains("type")) fail(field + ".type", "is required (\"perspective\" or \"orthographic\")");
      typed(*cameras[i], "type", field, &json::is_string, "a string");
      const std::string type = (*cameras[i])["type"].get<std::string>();
      if ((type == "perspective" || type == "orthographic") && !cameras[i]->contains(type)) {
        fail(field + "." + type, "is required for a camera of type \"" + type + "\"");
      }
      if (cameras[i]->contains("orthographic")) {
        const json& orthographic = member(*cameras[i], "orthographic", field);
        const std::string owner = field + ".orthographic";
        for (const char* key : {"xmag", "ymag", "znear", "zfar"}) {
          if (!orthographic.contains(key)) fail(owner + "." + key, "is required");
          typed(orthographic, key, owner, &json::is_number, "a number");
        }
      }
      if (!cameras[i]->contains("perspective")) continue;
      const json& perspective = member(*cameras[i], "perspective", field);
      const std::string owner = field + ".perspective";
      for (const char* key : {"aspectRatio", "yfov", "znear", "zfar"}) {
        typed(perspective, key, owner, &json::is_number, "a number");
      }
      const auto aspect = perspective.find("aspectRatio");
      if (aspect != perspective.end() && *aspect <= 0) {
        if (context_.policy.strict) fail(owner + ".aspectRatio", "must be positive (got " + quoteJson(*aspect) + ")");
        warnOnce(context_.path + ": " + owner + ".aspectRatio: " + quoteJson(*aspect) + " is not an aspect ratio; "
                 "the frame's own is used, as for any camera (--strict refuses it)");
      }
    }
  }

  void attributes(const json& object, const char* key, const std::string& owner) const {
    if (!object.contains(key)) return;
    const json& map = member(object, key, owner);
    for (auto it = map.begin(); it != map.end(); ++it) index(map, it.key().c_str(), join(owner, key), "accessors");
  }

  void checkMeshes() const {
    const std::vector<const json*> meshs = objects(doc_, "meshes", "meshes");
    for (std::size_t i = 0; i < meshs.size(); ++i) {
      const json* mesh = meshs[i];
      const std::string field = item("meshes", i);
      const std::vector<const json*> primitives = objects(*mesh, "primitives", field + ".primitives");
      // Empty, which the specification forbids, is what three.js draws as nothing: tolerated with a warning.
      if (primitives.empty() && context_.policy.strict) fail(field + ".primitives", "is required (at least one)");
      if (primitives.empty()) {
        warnOnce(context_.path + ": " + field + ".primitives: none (the specification asks for at least one): the "
                 "mesh draws nothing (--strict refuses it)");
      }
      for (std::size_t p = 0; p < primitives.size(); ++p) {
        const json* primitive = primitives[p];
        const std::string name = field + "." + item("primitives", p);
        if (!primitive->contains("attributes")) fail(name + ".attributes", "is required (at least POSITION)");
        attributes(*primitive, "attributes", name);
        index(*primitive, "indices", name, "accessors");
        index(*primitive, "material", name, "materials");
        integer(*primitive, "mode", name, 6);
        const std::vector<const json*> targets = objects(*primitive, "targets", name + ".targets");
        for (std::size_t t = 0; t < targets.size(); ++t) {
          const json* target = targets[t];
          for (auto it = target->begin(); it != target->end(); ++it) {
            index(*target, it.key().c_str(), name + "." + item("targets", t), "accessors");
          }
        }
      }
    }
  }

  void checkNodes() const {
    const std::vector<const json*> nodes = objects(doc_, "nodes", "nodes");
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const json* node = nodes[i];
      const std::string field = item("nodes", i);
      index(*node, "camera", field, "cameras");
      index(*node, "skin", field, "skins");
      index(*node, "mesh", field, "meshes");
      indexArray(*node, "children", field, "nodes");
      numbers(*node, "matrix", field, 16);
      numbers(*node, "translation", field, 3);
      numbers(*node, "rotation", field, 4);
      numbers(*node, "scale", field, 3);
      // The specification forbids a matrix beside TRS; viewers use the matrix, as the loader does.
      const bool trs = node->contains("translation") || node->contains("rotation") || node->contains("scale");
      if (node->contains("matrix") && trs && context_.policy.strict) {
        fail(field + ".matrix", "given with translation, rotation or scale (the specification allows one or the "
                                "other)");
      } else if (node->contains("matrix") && trs) {
        warnOnce(context_.path + ": " + field + ".matrix: given with translation, rotation or scale; the matrix is "
                 "used and they are ignored (--strict refuses it)");
      }
    }
  }

  const json& doc_;
  const GltfJsonContext& context_;
  std::vector<uint64_t> bufferLengths_;
  std::vector<View> views_;
};

}  // namespace

void checkGltfJson(const json& doc, const GltfJsonContext& context) { Checker(doc, context).run(); }

}  // namespace pbr
