#include "core/io/image_output.hpp"

#include <stb_image_write.h>
#include <tinyexr.h>

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <vector>

#include "core/io/output_file.hpp"
#include "core/scene/file_names.hpp"

namespace pbr {

namespace {

void appendToStream(void* context, void* data, int size) {
  static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
}

}  // namespace

HdrFileFormat hdrFileFormat(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".exr") return HdrFileFormat::Exr;
  if (ext == ".pfm") return HdrFileFormat::Pfm;
  throw std::invalid_argument(path + ": HDR captures must end in .exr or .pfm");
}

LdrFileFormat ldrFileFormat(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".png" || isStreamTarget(path)) return LdrFileFormat::Png;
  if (ext == ".jpg" || ext == ".jpeg") return LdrFileFormat::Jpeg;
  throw std::invalid_argument(path + ": images must end in .png, .jpg or .jpeg");
}


void writePng(std::ostream& out, const ImageRgba8& image) {
  if (!stbi_write_png_to_func(appendToStream, &out, image.width, image.height, 4, image.pixels.data(),
                              image.width * 4)) {
    throw std::runtime_error("could not encode PNG");
  }
}

void writeJpeg(std::ostream& out, const ImageRgba8& image) {
  constexpr int kQuality = 95;
  if (!stbi_write_jpg_to_func(appendToStream, &out, image.width, image.height, 4, image.pixels.data(), kQuality)) {
    throw std::runtime_error("could not encode JPEG");
  }
}

void writeLdr(std::ostream& out, LdrFileFormat format, const ImageRgba8& image) {
  if (format == LdrFileFormat::Jpeg) {
    writeJpeg(out, image);
  } else {
    writePng(out, image);
  }
}

void writeExr(std::ostream& out, const ImageRgbaF& image) {
  // One plane per channel, in the B, G, R order EXR viewers expect; float32 kept so that captures are exact
  // linear radiance.
  const size_t count = static_cast<size_t>(image.width) * image.height;
  std::vector<float> planes[3];
  for (int c = 0; c < 3; ++c) {
    planes[c].resize(count);
    for (size_t i = 0; i < count; ++i) planes[c][i] = image.pixels[i * 4 + 2 - c];
  }
  float* planePointers[3] = {planes[0].data(), planes[1].data(), planes[2].data()};
  EXRImage exr;
  InitEXRImage(&exr);
  exr.num_channels = 3;
  exr.width = image.width;
  exr.height = image.height;
  exr.images = reinterpret_cast<unsigned char**>(planePointers);
  EXRChannelInfo channels[3] = {};
  int pixelTypes[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
  for (int c = 0; c < 3; ++c) channels[c].name[0] = "BGR"[c];
  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = 3;
  header.channels = channels;
  header.pixel_types = pixelTypes;
  header.requested_pixel_types = pixelTypes;
  header.compression_type = image.width < 16 && image.height < 16 ? TINYEXR_COMPRESSIONTYPE_NONE
                                                                   : TINYEXR_COMPRESSIONTYPE_ZIP;
  unsigned char* memory = nullptr;
  const char* err = nullptr;
  const size_t bytes = SaveEXRImageToMemory(&exr, &header, &memory, &err);
  std::unique_ptr<unsigned char, void (*)(void*)> owned(memory, std::free);
  if (bytes == 0) {
    const std::string reason = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    throw std::runtime_error("could not encode EXR: " + reason);
  }
  out.write(reinterpret_cast<const char*>(memory), static_cast<std::streamsize>(bytes));
}

void writePfm(std::ostream& out, const ImageRgbaF& image) {
  // A negative scale marks little-endian data; PFM stores rows from the bottom.
  out << "PF\n" << image.width << ' ' << image.height << "\n-1.0\n";
  std::vector<float> row(static_cast<size_t>(image.width) * 3);
  for (int y = image.height - 1; y >= 0; --y) {
    for (int x = 0; x < image.width; ++x) {
      for (int c = 0; c < 3; ++c) row[static_cast<size_t>(x) * 3 + c] = image.at(x, y)[c];
    }
    out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size() * sizeof(float)));
  }
}

void writeHdr(std::ostream& out, HdrFileFormat format, const ImageRgbaF& image) {
  if (format == HdrFileFormat::Exr) writeExr(out, image);
  else writePfm(out, image);
}

void writePng(const std::string& path, const ImageRgba8& image) {
  writeOutputFile(path, [&](std::ostream& out) { writePng(out, image); });
}

void writeLdr(const std::string& path, const ImageRgba8& image) {
  const LdrFileFormat format = ldrFileFormat(path);
  writeOutputFile(path, [&](std::ostream& out) { writeLdr(out, format, image); });
}

void writeHdr(const std::string& path, const ImageRgbaF& image) {
  const HdrFileFormat format = hdrFileFormat(path);
  writeOutputFile(path, [&](std::ostream& out) { writeHdr(out, format, image); });
}

}  // namespace pbr
