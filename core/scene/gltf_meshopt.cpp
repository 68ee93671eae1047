#include "core/scene/gltf_meshopt.hpp"

#include <meshoptimizer.h>

#include <string>
#include <vector>

namespace pbr {

namespace {

// What a decoded view may hold at most: the accessor limits' 2 GiB.
constexpr uint64_t kMaxDecodedBytes = uint64_t(1) << 31;

}  // namespace

void decodeMeshoptViews(GltfFile& file) {
  tinygltf::Model& model = file.model;
  for (size_t v = 0; v < model.bufferViews.size(); ++v) {
    tinygltf::BufferView& view = model.bufferViews[v];
    const auto extension = view.extensions.find("EXT_meshopt_compression");
    if (extension == view.extensions.end()) continue;
    const std::string name = gltfElement("bufferViews", static_cast<int>(v)) + ".extensions.EXT_meshopt_compression";
    const tinygltf::Value& e = extension->second;
    const auto integer = [&](const char* key, bool required, int64_t fallback) -> uint64_t {
      const tinygltf::Value& x = e.Get(key);
      if (!e.Has(key)) {
        if (required) file.fail(name + "." + key + ": missing");
        return static_cast<uint64_t>(fallback);
      }
      if (!x.IsNumber() || x.GetNumberAsDouble() < 0.0 || x.GetNumberAsDouble() > double(kMaxDecodedBytes) ||
          x.GetNumberAsDouble() != double(int64_t(x.GetNumberAsDouble()))) {
        file.fail(name + "." + key + ": must be an integer in [0, 2147483648]");
      }
      return static_cast<uint64_t>(x.GetNumberAsDouble());
    };
    const auto text = [&](const char* key, const char* fallback) {
      const tinygltf::Value& x = e.Get(key);
      if (!e.Has(key)) return std::string(fallback);
      if (!x.IsString()) file.fail(name + "." + key + ": must be a string");
      return x.Get<std::string>();
    };
    const uint64_t buffer = integer("buffer", true, 0), offset = integer("byteOffset", false, 0),
                   length = integer("byteLength", true, 0), stride = integer("byteStride", true, 0),
                   count = integer("count", true, 0);
    const std::string mode = text("mode", ""), filter = text("filter", "NONE");
    if (buffer >= model.buffers.size()) file.fail(name + ".buffer: no buffer " + std::to_string(buffer));
    const std::vector<unsigned char>& source = model.buffers[buffer].data;
    if (offset > source.size() || length > source.size() - offset) {
      file.fail(name + ": byteOffset " + std::to_string(offset) + " + byteLength " + std::to_string(length) +
                " run past the end of buffers[" + std::to_string(buffer) + "] (" + std::to_string(source.size()) +
                " bytes)");
    }
    if (count == 0 || stride == 0 || count * stride > kMaxDecodedBytes) {
      file.fail(name + ": count " + std::to_string(count) + " x byteStride " + std::to_string(stride) +
                " is empty or over 2 GiB");
    }
    std::vector<unsigned char> decoded(count * stride);
    const unsigned char* data = source.data() + offset;
    int status = 0;
    if (mode == "ATTRIBUTES") {
      if (stride % 4 != 0 || stride > 256) {
        file.fail(name + ".byteStride: " + std::to_string(stride) + " for ATTRIBUTES (a multiple of 4, at most 256)");
      }
      const bool filterFits = filter == "NONE" || (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8)) ||
                              (filter == "QUATERNION" && stride == 8) || filter == "EXPONENTIAL";
      if (!filterFits) {
        file.fail(name + ".filter: '" + filter + "' with byteStride " + std::to_string(stride) +
                  " (NONE, OCTAHEDRAL with 4 or 8, QUATERNION with 8, EXPONENTIAL)");
      }
      status = meshopt_decodeVertexBuffer(decoded.data(), count, stride, data, length);
      if (status == 0 && filter == "OCTAHEDRAL") meshopt_decodeFilterOct(decoded.data(), count, stride);
      if (status == 0 && filter == "QUATERNION") meshopt_decodeFilterQuat(decoded.data(), count, stride);
      if (status == 0 && filter == "EXPONENTIAL") meshopt_decodeFilterExp(decoded.data(), count, stride);
    } else if (mode == "TRIANGLES" || mode == "INDICES") {
      if (stride != 2 && stride != 4) {
        file.fail(name + ".byteStride: " + std::to_string(stride) + " for indices (2 or 4)");
      }
      if (filter != "NONE") file.fail(name + ".filter: '" + filter + "' for " + mode + " (only NONE)");
      if (mode == "TRIANGLES" && count % 3 != 0) {
        file.fail(name + ".count: " + std::to_string(count) + " TRIANGLES indices are not whole triangles");
      }
      status = mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(decoded.data(), count, stride, data, length)
                                   : meshopt_decodeIndexSequence(decoded.data(), count, stride, data, length);
    } else {
      file.fail(name + ".mode: '" + mode + "' is not ATTRIBUTES, TRIANGLES or INDICES");
    }
    if (status != 0) file.fail(name + ": the compressed data does not decode (meshoptimizer status " +
                               std::to_string(status) + ")");
    // The view now reads the decoded bytes, from a buffer of their own.
    tinygltf::Buffer out;
    out.data = std::move(decoded);
    model.buffers.push_back(std::move(out));
    view.buffer = static_cast<int>(model.buffers.size()) - 1;
    view.byteOffset = 0;
    view.byteLength = count * stride;
  }
}

}  // namespace pbr
