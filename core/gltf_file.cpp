#include "core/gltf_file.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iostream>

#include "core/scene.hpp"

namespace pbr {

namespace {

// tinygltf's default expands paths with wordexp(3), which runs shell expansion on names taken from the file.
std::string keepPath(const std::string& path, void*) { return path; }

// Keeps the encoded bytes of URI and data-URI images; buffer-view images are left for the caller to validate.
bool keepEncodedImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
  if (image->bufferView >= 0 || index < 0 || size <= 0) return true;
  auto& encoded = *static_cast<std::vector<std::vector<unsigned char>>*>(user);
  if (encoded.size() <= static_cast<size_t>(index)) encoded.resize(static_cast<size_t>(index) + 1);
  encoded[static_cast<size_t>(index)].assign(bytes, bytes + size);
  return true;
}

std::string firstLine(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
  return line;
}

bool isGlb(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  return in.read(magic, 4) && std::memcmp(magic, "glTF", 4) == 0;
}

}  // namespace

void GltfFile::fail(const std::string& what) const { throw SceneError(path + ": " + what); }

void GltfFile::warn(const std::string& what) const { std::cerr << path << ": " << what << "\n"; }

GltfFile readGltfFile(const std::string& path) {
  GltfFile file;
  file.path = path;
  if (!std::ifstream(path, std::ios::binary)) file.fail("cannot open the file");

  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(
      {&tinygltf::FileExists, &keepPath, &tinygltf::ReadWholeFile, &tinygltf::WriteWholeFile, nullptr});
  loader.SetImageLoader(&keepEncodedImage, &file.encodedImages);
  std::string err, warn;
  const bool ok = isGlb(path) ? loader.LoadBinaryFromFile(&file.model, &err, &warn, path)
                              : loader.LoadASCIIFromFile(&file.model, &err, &warn, path);
  if (!ok) file.fail(firstLine(!err.empty() ? err : !warn.empty() ? warn : "not a valid glTF 2.0 file"));
  file.encodedImages.resize(file.model.images.size());

  for (const std::string& required : file.model.extensionsRequired) {
    const bool supported = std::any_of(std::begin(kSupportedGltfExtensions), std::end(kSupportedGltfExtensions),
                                       [&](const char* name) { return required == name; });
    if (!supported) file.fail("extensionsRequired: " + required + " is not supported");
  }
  return file;
}

}  // namespace pbr
