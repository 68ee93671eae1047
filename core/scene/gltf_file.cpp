#include "core/scene/gltf_file.hpp"
#include "core/scene/file_names.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <system_error>

#include <nlohmann/json.hpp>

#include "core/scene/glb_container.hpp"
#include "core/scene/gltf_json_check.hpp"
#include "core/scene/gltf_meshopt.hpp"
#include "core/scene/input_file.hpp"
#include "core/scene/json_file.hpp"
#include "core/scene/json_text.hpp"
#include "core/scene/messages.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

namespace {

namespace fs = std::filesystem;

// tinygltf's default expands paths with wordexp(3), which runs shell expansion on names taken from the file.
std::string keepPath(const std::string& path, void*) { return path; }

// tinygltf looks for a URI's file in the model's folder and then in the working directory; checkGltfJson has
// already found every URI in the model's folder, so the second place never answers. Reading goes through
// readInputFile like every other input.
bool isRegularFile(const std::string& path, void*) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}
bool readFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  try {
    const std::string bytes = readInputFile(path);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const std::runtime_error& e) {
    *err = e.what();
    return false;
  }
}

// Keeps the encoded bytes of URI and data-URI images; buffer-view images are left for the caller to validate.
bool keepEncodedImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
  if (image->bufferView >= 0 || index < 0 || size <= 0) return true;
  auto& encoded = *static_cast<std::vector<std::vector<unsigned char>>*>(user);
  if (encoded.size() <= static_cast<size_t>(index)) encoded.resize(static_cast<size_t>(index) + 1);
  encoded[static_cast<size_t>(index)].assign(bytes, bytes + size);
  return true;
}

// tinygltf's first message line, cut short: its messages may quote a whole data: URI.
std::string firstLine(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
  return line.size() <= 160 ? line : line.substr(0, 157) + "...";
}

bool isSupportedExtension(const std::string& name) {
  return std::any_of(std::begin(kSupportedGltfExtensions), std::end(kSupportedGltfExtensions),
                     [&](const char* supported) { return name == supported; });
}

// The document as tinygltf 2.7 can read it, or nothing where it can read it as written. Two things valid glTF it
// refuses are rewritten (and a mistake viewers tolerate): a primitive whose indices accessor has no bufferView, which is how
// KHR_draco_mesh_compression files write it (the primitive loses "indices": they are in the Draco data), and a
// buffer without a URI besides a GLB's first, which is how EXT_meshopt_compression writes a fallback buffer that
// holds no data (it gets a 3-byte stand-in: its views are decoded from compressed ones, gltf_meshopt.hpp). A spot
// light without a "spot" object, which tinygltf refuses, gets an empty one: the default cone.
std::optional<nlohmann::json> readableByTinygltf(const nlohmann::json& doc) {
  std::optional<nlohmann::json> out;
  const auto meshes = doc.find("meshes");
  for (size_t m = 0; meshes != doc.end() && meshes->is_array() && m < meshes->size(); ++m) {
    const nlohmann::json& mesh = (*meshes)[m];
    const auto primitives = mesh.is_object() ? mesh.find("primitives") : mesh.end();
    if (!mesh.is_object() || primitives == mesh.end() || !primitives->is_array()) continue;
    for (size_t p = 0; p < primitives->size(); ++p) {
      const nlohmann::json& primitive = (*primitives)[p];
      if (!primitive.is_object() || !primitive.contains("indices") || !primitive.contains("extensions") ||
          !primitive["extensions"].is_object() || !primitive["extensions"].contains("KHR_draco_mesh_compression")) {
        continue;
      }
      if (!out) out = doc;
      (*out)["meshes"][m]["primitives"][p].erase("indices");
    }
  }
  // A spot light without its cone (checkGltfJson warns): tinygltf refuses it, the default cone is drawn.
  const auto extensions = doc.find("extensions");
  if (extensions != doc.end() && extensions->is_object() && extensions->contains("KHR_lights_punctual") &&
      (*extensions)["KHR_lights_punctual"].is_object() && (*extensions)["KHR_lights_punctual"].contains("lights") &&
      (*extensions)["KHR_lights_punctual"]["lights"].is_array()) {
    const nlohmann::json& lights = (*extensions)["KHR_lights_punctual"]["lights"];
    for (size_t i = 0; i < lights.size(); ++i) {
      const nlohmann::json& light = lights[i];
      if (!light.is_object() || !light.contains("type") || light["type"] != "spot" ||
          (light.contains("spot") && !light["spot"].is_null())) {
        continue;
      }
      if (!out) out = doc;
      (*out)["extensions"]["KHR_lights_punctual"]["lights"][i]["spot"] = nlohmann::json::object();
    }
  }
  const auto buffers = doc.find("buffers");
  for (size_t i = 0; buffers != doc.end() && buffers->is_array() && i < buffers->size(); ++i) {
    const nlohmann::json& buffer = (*buffers)[i];
    if (!isMeshoptFallback(buffer) || buffer.contains("uri")) continue;
    if (!out) out = doc;
    (*out)["buffers"][i]["uri"] = "data:application/octet-stream;base64,AAAA";
    (*out)["buffers"][i]["byteLength"] = 3;
  }
  return out;
}

// The asset's glTF version: "2.x", and a minVersion this loader (glTF 2.0) meets; a file of another major version
// is another format, one needing a later minor version may use what 2.0 lacks (glTF 2.0, 3.2).
void checkAssetVersion(const nlohmann::json& doc, const std::string& path) {
  const auto asset = doc.is_object() ? doc.find("asset") : doc.end();
  if (!doc.is_object() || asset == doc.end() || !asset->is_object()) return;  // tinygltf names a missing asset
  for (const char* key : {"version", "minVersion"}) {
    const auto v = asset->find(key);
    if (v == asset->end()) continue;
    const std::string text = v->is_string() ? v->get<std::string>() : "";
    const size_t dot = text.find('.');
    const bool form = dot != std::string::npos && dot > 0 && dot + 1 < text.size() &&
                      text.find_first_not_of("0123456789.") == std::string::npos &&
                      text.find('.', dot + 1) == std::string::npos;
    const std::string major = form ? text.substr(0, dot) : "", minor = form ? text.substr(dot + 1) : "";
    const bool meets = form && major == "2" && (std::string(key) == "version" || minor == "0");
    if (!meets) {
      throw SceneError(path + ": asset." + key + ": " + jsonText(*v) +
                       (form ? " is not a glTF version this loader reads (2.0)" : " is not a version like \"2.0\""));
    }
  }
}

// A required extension outside kSupportedGltfExtensions refuses the file, checked before its structure: a mesh only
// the extension decodes (Draco, meshopt) has buffers and accessors that look broken without it, and the message
// is to name the extension, not what it explains. Anything but an array of strings is left to checkGltfJson.
void checkRequiredExtensions(const nlohmann::json& doc, const std::string& path) {
  const auto required = doc.is_object() ? doc.find("extensionsRequired") : doc.end();
  if (!doc.is_object() || required == doc.end() || !required->is_array()) return;
  for (size_t i = 0; i < required->size(); ++i) {
    const nlohmann::json& name = (*required)[i];
    if (!name.is_string()) {
      throw SceneError(path + ": extensionsRequired[" + std::to_string(i) + "]: must be an extension name (got " +
                       jsonText(name) + ")");
    }
    if (isSupportedExtension(name.get<std::string>())) continue;
    const std::string extension = name.get<std::string>();
    throw SceneError(path + ": extensionsRequired: " + jsonText(extension) + " is not supported" +
                     (extension == "KHR_texture_basisu" ? " (no Debian package transcodes Basis Universal textures)"
                                                        : ""));
  }
}

}  // namespace

void GltfFile::fail(const std::string& what) const { throw SceneError(path + ": " + what); }

void GltfFile::warn(const std::string& what) const { warnOnce(path + ": " + what); }

GltfFile readGltfFile(const std::string& path, const UriPolicy& policy) {
  GltfFile file;
  file.path = path;
  file.policy = policy;
  std::string bytes;
  try {
    bytes = readInputFile(path);
  } catch (const std::runtime_error& e) {
    throw SceneError(e.what());
  }
  // A .glb is read as GLB whatever its first bytes, so that a damaged header is reported as such.
  const bool glb = hasGlbMagic(bytes) || lowerExtension(path) == ".glb";
  GltfJsonContext context{path, fs::path(path).parent_path(), policy, std::nullopt};
  std::string jsonText;
  if (glb) {
    const GlbChunks chunks = readGlbChunks(bytes, path);
    jsonText = chunks.json;
    if (chunks.hasBin) context.binChunk = chunks.binLength;
    // The specification pads the JSON chunk with spaces; NUL padding, which some writers use, is read as spaces.
    const size_t end = jsonText.find_last_not_of('\0');
    if (end + 1 < jsonText.size() && end != std::string::npos) {
      if (policy.strict) throw SceneError(path + ": the JSON chunk is padded with NUL bytes, not spaces");
      file.warn("the JSON chunk is padded with NUL bytes, read as the spaces the specification asks for (--strict "
                "refuses it)");
      jsonText.resize(end + 1);
    }
  }
  std::vector<std::string> duplicates;
  const nlohmann::json doc = parseJsonText(glb ? jsonText : bytes, path, &duplicates);
  for (const std::string& field : duplicates) {
    if (policy.strict) throw SceneError(path + ": " + field + ": given twice in one object (--strict refuses it)");
    file.warn(field + ": given twice in one object; the later value is used, as JSON.parse and the viewers read it "
              "(--strict refuses it)");
  }
  checkAssetVersion(doc, path);
  checkRequiredExtensions(doc, path);
  checkGltfJson(doc, context);

  const std::optional<nlohmann::json> rewritten = readableByTinygltf(doc);
  if (rewritten) {
    // checkGltfJson has checked the file as written; tinygltf reads the rewritten document.
    const std::string text = rewritten->dump();
    bytes = glb ? withGlbJson(bytes, readGlbChunks(bytes, path), text) : text;
  }
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&isRegularFile, &keepPath, &readFile, &tinygltf::WriteWholeFile, nullptr});
  loader.SetImageLoader(&keepEncodedImage, &file.encodedImages);
  std::string err, warn;
  const std::string folder = context.folder.empty() ? "." : context.folder.string();
  const bool ok =
      glb ? loader.LoadBinaryFromMemory(&file.model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                        static_cast<unsigned int>(bytes.size()), folder)
          : loader.LoadASCIIFromString(&file.model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()),
                                       folder);
  if (!ok) file.fail(firstLine(!err.empty() ? err : !warn.empty() ? warn : "not a valid glTF 2.0 file"));
  file.encodedImages.resize(file.model.images.size());
  file.imageMimeTypes.assign(file.model.images.size(), "");
  if (const auto images = doc.find("images"); images != doc.end() && images->is_array()) {
    for (size_t i = 0; i < images->size() && i < file.imageMimeTypes.size(); ++i) {
      const nlohmann::json& image = (*images)[i];
      if (image.is_object() && image.contains("mimeType") && image["mimeType"].is_string()) {
        file.imageMimeTypes[i] = image["mimeType"].get<std::string>();
      }
    }
  }
  decodeMeshoptViews(file);

  // The file is meant to look right without these, or it would require them; it may still look different.
  std::string ignored;
  for (const std::string& used : file.model.extensionsUsed) {
    if (!isSupportedExtension(used)) ignored += (ignored.empty() ? "" : ", ") + used;
  }
  if (!ignored.empty()) file.warn("extensionsUsed not implemented, ignored: " + ignored);
  return file;
}

}  // namespace pbr
