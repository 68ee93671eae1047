#include "core/scene/gltf_accessor.hpp"

#include <algorithm>
#include <cstring>

namespace pbr {

namespace {

constexpr size_t kMaxZeroElements = size_t(1) << 26;

const tinygltf::Accessor& accessorAt(const GltfFile& file, int index, const std::string& field) {
  if (index < 0 || static_cast<size_t>(index) >= file.model.accessors.size()) {
    file.fail(field + ": no accessor " + std::to_string(index) + " (the file has " +
              std::to_string(file.model.accessors.size()) + ")");
  }
  const tinygltf::Accessor& a = file.model.accessors[static_cast<size_t>(index)];
  if (a.count < 1) file.fail(gltfElement("accessors", index) + ": count must be at least 1");
  return a;
}

std::string typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
      return "VEC2";
    case TINYGLTF_TYPE_VEC3:
      return "VEC3";
    case TINYGLTF_TYPE_VEC4:
      return "VEC4";
    case TINYGLTF_TYPE_MAT4:
      return "MAT4";
    default:
      return "type " + std::to_string(type);
  }
}

size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

template <class T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Where element i of an accessor starts: `base` and `stride` after the bounds check, or no data at all for an
// accessor without a buffer view (all zeros, as glTF specifies).
struct Elements {
  const unsigned char* base = nullptr;
  size_t stride = 0;
};

Elements locate(const GltfFile& file, int index, const tinygltf::Accessor& a, int components) {
  const size_t elementSize = componentSize(a.componentType) * static_cast<size_t>(components);
  const std::string name = gltfElement("accessors", index);
  if (a.bufferView < 0) {
    // Without a view the count is bounded by nothing in the file; refuse what could only exhaust memory.
    if (a.count > kMaxZeroElements) file.fail(name + ": count " + std::to_string(a.count) + " without a bufferView");
    return {};
  }
  const ByteSpan view = bufferViewBytes(file, a.bufferView, name + ".bufferView");
  const size_t declaredStride = file.model.bufferViews[static_cast<size_t>(a.bufferView)].byteStride;
  const size_t stride = declaredStride ? declaredStride : elementSize;
  if (stride < elementSize) {
    file.fail(gltfElement("bufferViews", a.bufferView) + ": byteStride " + std::to_string(stride) +
              " is smaller than the " + std::to_string(elementSize) + "-byte elements of " + name);
  }
  // offset + (count - 1) * stride + elementSize <= view size, arranged so that nothing can overflow.
  const bool fits = a.byteOffset <= view.size && elementSize <= view.size - a.byteOffset &&
                    a.count - 1 <= (view.size - a.byteOffset - elementSize) / stride;
  if (!fits) {
    file.fail(name + ": " + std::to_string(a.count) + " elements of " + std::to_string(elementSize) +
              " bytes (stride " + std::to_string(stride) + ") from byteOffset " + std::to_string(a.byteOffset) +
              " run past the end of bufferViews[" + std::to_string(a.bufferView) + "] (" + std::to_string(view.size) +
              " bytes)");
  }
  return {view.data + a.byteOffset, stride};
}

float component(const unsigned char* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return load<float>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? *p / 255.0f : *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const float v = load<uint16_t>(p);
      return normalized ? v / 65535.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float v = load<int8_t>(p);
      return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const float v = load<int16_t>(p);
      return normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    default:
      return static_cast<float>(load<uint32_t>(p));
  }
}

std::string componentName(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return "FLOAT";
    default:
      return std::to_string(componentType);
  }
}

void checkFormat(const GltfFile& file, int index, const tinygltf::Accessor& a, int type,
                 std::initializer_list<int> componentTypes, const std::string& field) {
  if (a.type != type) {
    file.fail(field + ": accessors[" + std::to_string(index) + "] is " + typeName(a.type) + ", expected " +
              typeName(type));
  }
  if (std::find(componentTypes.begin(), componentTypes.end(), a.componentType) == componentTypes.end()) {
    std::string allowed;
    for (const int c : componentTypes) allowed += (allowed.empty() ? "" : " or ") + componentName(c);
    file.fail(field + ": accessors[" + std::to_string(index) + "] has componentType " + componentName(a.componentType) +
              ", expected " + allowed);
  }
}

// glTF sparse storage: `sparse.count` (index, value) pairs replace elements of the accessor's base (its view's data,
// or zeros without one). Calls set(element, value bytes) for each pair in order, after checking that both views
// hold them and that every index names an element.
template <class Set>
void forEachSparse(const GltfFile& file, int index, const tinygltf::Accessor& a, size_t elementSize, Set set) {
  if (!a.sparse.isSparse) return;
  const std::string name = gltfElement("accessors", index) + ".sparse";
  const int indexType = a.sparse.indices.componentType;
  if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    file.fail(name + ".indices.componentType: " + componentName(indexType) +
              ", expected UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  }
  const size_t count = static_cast<size_t>(a.sparse.count), indexSize = componentSize(indexType);
  // Each of count elements of `size` bytes from `offset` lies inside `span`; none of it can overflow (count and
  // offset are at most 2^31, size at most 64).
  const auto inside = [&](const ByteSpan& span, size_t offset, size_t size, const std::string& field) {
    if (offset > span.size || count * size > span.size - offset) {
      file.fail(field + ": " + std::to_string(count) + " elements of " + std::to_string(size) +
                " bytes from byteOffset " + std::to_string(offset) + " run past the end of its bufferView (" +
                std::to_string(span.size) + " bytes)");
    }
    return span.data + offset;
  };
  const unsigned char* indices =
      inside(bufferViewBytes(file, a.sparse.indices.bufferView, name + ".indices.bufferView"),
             static_cast<size_t>(a.sparse.indices.byteOffset), indexSize, name + ".indices");
  const unsigned char* values = inside(bufferViewBytes(file, a.sparse.values.bufferView, name + ".values.bufferView"),
                                       static_cast<size_t>(a.sparse.values.byteOffset), elementSize, name + ".values");
  for (size_t i = 0; i < count; ++i) {
    const unsigned char* p = indices + i * indexSize;
    const size_t element = indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? *p
                           : indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? load<uint16_t>(p)
                                                                                 : load<uint32_t>(p);
    if (element >= a.count) {
      file.fail(name + ".indices: index " + std::to_string(element) + " at position " + std::to_string(i) +
                " is out of range (the accessor has " + std::to_string(a.count) + " elements)");
    }
    set(element, values + i * elementSize);
  }
}

}  // namespace

int componentsOf(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
    case TINYGLTF_TYPE_VEC3:
    case TINYGLTF_TYPE_VEC4:
      return type;
    case TINYGLTF_TYPE_MAT4:
      return 16;
    default:
      return 0;
  }
}

ByteSpan bufferViewBytes(const GltfFile& file, int index, const std::string& field) {
  const auto& views = file.model.bufferViews;
  if (index < 0 || static_cast<size_t>(index) >= views.size()) {
    file.fail(field + ": no bufferView " + std::to_string(index) + " (the file has " + std::to_string(views.size()) +
              ")");
  }
  const tinygltf::BufferView& v = views[static_cast<size_t>(index)];
  const std::string name = gltfElement("bufferViews", index);
  if (v.buffer < 0 || static_cast<size_t>(v.buffer) >= file.model.buffers.size()) {
    file.fail(name + ": no buffer " + std::to_string(v.buffer));
  }
  const std::vector<unsigned char>& buffer = file.model.buffers[static_cast<size_t>(v.buffer)].data;
  if (v.byteLength > buffer.size() || v.byteOffset > buffer.size() - v.byteLength) {
    file.fail(name + ": byteOffset + byteLength past the end of buffer " + std::to_string(v.buffer) + " (" +
              std::to_string(v.byteOffset) + " + " + std::to_string(v.byteLength) + " > " +
              std::to_string(buffer.size()) + ")");
  }
  return {buffer.data() + v.byteOffset, v.byteLength};
}

size_t accessorCount(const GltfFile& file, int accessor, const std::string& field) {
  return accessorAt(file, accessor, field).count;
}

std::vector<float> readFloatAccessor(const GltfFile& file, int index, int type,
                                     std::initializer_list<int> componentTypes, const std::string& field) {
  const tinygltf::Accessor& a = accessorAt(file, index, field);
  checkFormat(file, index, a, type, componentTypes, field);
  const int components = componentsOf(type);
  const Elements e = locate(file, index, a, components);
  std::vector<float> out(a.count * static_cast<size_t>(components), 0.0f);
  const size_t size = componentSize(a.componentType);
  const auto set = [&](size_t i, const unsigned char* element) {
    for (int c = 0; c < components; ++c) {
      out[i * components + c] = component(element + c * size, a.componentType, a.normalized);
    }
  };
  if (e.base) {
    for (size_t i = 0; i < a.count; ++i) set(i, e.base + i * e.stride);
  }
  forEachSparse(file, index, a, size * static_cast<size_t>(components), set);
  return out;
}

std::vector<uint32_t> readIndexAccessor(const GltfFile& file, int index, size_t vertexCount, const std::string& field) {
  const tinygltf::Accessor& a = accessorAt(file, index, field);
  checkFormat(file, index, a, TINYGLTF_TYPE_SCALAR,
              {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
               TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
              field);
  const Elements e = locate(file, index, a, 1);
  std::vector<uint32_t> out(a.count, 0u);
  const auto set = [&](size_t i, const unsigned char* p) {
    out[i] = a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? *p
             : a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? load<uint16_t>(p)
                                                                         : load<uint32_t>(p);
  };
  if (e.base) {
    for (size_t i = 0; i < a.count; ++i) set(i, e.base + i * e.stride);
  }
  forEachSparse(file, index, a, componentSize(a.componentType), set);
  for (size_t i = 0; i < out.size(); ++i) {
    if (out[i] >= vertexCount) {
      file.fail(field + ": index " + std::to_string(out[i]) + " at position " + std::to_string(i) + " of accessors[" +
                std::to_string(index) + "] is out of range (" + std::to_string(vertexCount) + " vertices)");
    }
  }
  return out;
}

}  // namespace pbr
