#pragma once
#include <ostream>
#include <string>

#include "core/scene/image.hpp"

namespace pbr {

// The file formats of captures, chosen by extension (case-insensitive). Throw std::invalid_argument naming the
// file for any other extension, so that a command can refuse the path before it renders anything.
// A device or FIFO (/dev/stdout) names no format: display images go there as PNG.
enum class HdrFileFormat { Exr, Pfm };
HdrFileFormat hdrFileFormat(const std::string& path);  // .exr or .pfm
enum class LdrFileFormat { Png, Jpeg };
LdrFileFormat ldrFileFormat(const std::string& path);  // .png, .jpg or .jpeg

// Encoders onto a stream (an OutputFile's, core/io/output_file.hpp, which checks the writes).
void writePng(std::ostream& out, const ImageRgba8& image);
void writeJpeg(std::ostream& out, const ImageRgba8& image);  // baseline, quality 95, alpha dropped
void writeLdr(std::ostream& out, LdrFileFormat format, const ImageRgba8& image);
void writeExr(std::ostream& out, const ImageRgbaF& image);  // RGB float32
void writePfm(std::ostream& out, const ImageRgbaF& image);  // RGB float32, little endian
void writeHdr(std::ostream& out, HdrFileFormat format, const ImageRgbaF& image);

// Whole files through an OutputFile: a failure throws std::runtime_error "PATH: cannot write: REASON" and leaves
// no file behind. writePng writes PNG whatever the name; writeLdr picks by the extension, as ldrFileFormat;
// writeHdr writes EXR or PFM by the extension, as hdrFileFormat.
void writePng(const std::string& path, const ImageRgba8& image);
void writeLdr(const std::string& path, const ImageRgba8& image);
void writeHdr(const std::string& path, const ImageRgbaF& image);

}  // namespace pbr
