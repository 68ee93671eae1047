#include "core/image.hpp"

#include <stb_image.h>
#include <stb_image_write.h>
#include <tinyexr.h>

#include <climits>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "core/input_file.hpp"

namespace pbr {

namespace {

void ensureParentDir(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

void writePng(const std::string& path, const ImageRgba8& image) {
  ensureParentDir(path);
  if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.pixels.data(), image.width * 4)) {
    throw std::runtime_error(path + ": could not write PNG");
  }
}

ImageRgba8 readPng(const std::string& path) {
  const std::string bytes = readInputFile(path);
  return decodeImage(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), path);
}

std::string decoderFailureReason() {
  const char* reason = stbi_failure_reason();
  return reason && *reason ? std::string(": ") + reason : std::string();
}

ImageRgba8 decodeImage(const unsigned char* bytes, size_t size, const std::string& name) {
  if (size == 0) throw std::runtime_error(name + ": cannot decode image: no data");
  if (size > static_cast<size_t>(INT_MAX)) throw std::runtime_error(name + ": cannot decode image: over 2 GiB");
  int w = 0, h = 0, n = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load_from_memory(bytes, static_cast<int>(size), &w, &h, &n, 4), stbi_image_free);
  if (!data) throw std::runtime_error(name + ": cannot decode image" + decoderFailureReason());
  ImageRgba8 img{w, h, {}};
  img.pixels.assign(data.get(), data.get() + static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
  return img;
}

void writeExr(const std::string& path, const ImageRgbaF& image) {
  ensureParentDir(path);
  const size_t count = static_cast<size_t>(image.width) * image.height;
  std::vector<float> rgb(count * 3);
  for (size_t i = 0; i < count; ++i) {
    for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = image.pixels[i * 4 + c];
  }
  const char* err = nullptr;
  // save_as_fp16 = 0: keep float32 so captures are exact linear radiance.
  if (SaveEXR(rgb.data(), image.width, image.height, 3, 0, path.c_str(), &err) != TINYEXR_SUCCESS) {
    const std::string reason = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    throw std::runtime_error(path + ": could not write EXR: " + reason);
  }
}

void writePfm(const std::string& path, const ImageRgbaF& image) {
  ensureParentDir(path);
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "wb"), std::fclose);
  if (!f) throw std::runtime_error(path + ": could not open for writing");
  // A negative scale marks little-endian data; PFM stores rows from the bottom.
  std::fprintf(f.get(), "PF\n%d %d\n-1.0\n", image.width, image.height);
  std::vector<float> row(static_cast<size_t>(image.width) * 3);
  for (int y = image.height - 1; y >= 0; --y) {
    for (int x = 0; x < image.width; ++x) {
      for (int c = 0; c < 3; ++c) row[static_cast<size_t>(x) * 3 + c] = image.at(x, y)[c];
    }
    if (std::fwrite(row.data(), sizeof(float), row.size(), f.get()) != row.size()) {
      throw std::runtime_error(path + ": write failed");
    }
  }
}

void writeHdr(const std::string& path, const ImageRgbaF& image) {
  const std::string ext = lowerExtension(path);
  if (ext == ".exr") return writeExr(path, image);
  if (ext == ".pfm") return writePfm(path, image);
  throw std::runtime_error(path + ": HDR captures must end in .exr or .pfm");
}

}  // namespace pbr
