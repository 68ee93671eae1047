#pragma once
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "core/scene/gltf_file.hpp"

namespace pbr {

// Checked reads from a glTF file's buffers: every index, size and offset is validated before a byte is read, and
// a failure names `field` (the referring property, e.g. "meshes[0].primitives[1].attributes.NORMAL") and the
// faulty object. All throw through GltfFile::fail.

struct ByteSpan {
  const unsigned char* data;
  size_t size;
};

// Components per element of a SCALAR, VEC2-4 or MAT4 accessor type (a TINYGLTF_TYPE_ value), 0 for the others.
int componentsOf(int type);

// The bytes of buffer view `view`.
ByteSpan bufferViewBytes(const GltfFile& file, int view, const std::string& field);

// Accessor `accessor` as floats, `type` components per element (a TINYGLTF_TYPE_ value), of one of the allowed
// component types; normalized integers map to [0,1] or [-1,1] as glTF specifies.
std::vector<float> readFloatAccessor(const GltfFile& file, int accessor, int type,
                                     std::initializer_list<int> componentTypes, const std::string& field);

// A SCALAR accessor of unsigned integers, each checked to be below `vertexCount`.
std::vector<uint32_t> readIndexAccessor(const GltfFile& file, int accessor, size_t vertexCount,
                                        const std::string& field);

// The element count of accessor `accessor`, checked to be at least 1.
size_t accessorCount(const GltfFile& file, int accessor, const std::string& field);

}  // namespace pbr
