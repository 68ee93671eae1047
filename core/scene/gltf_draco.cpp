#include "core/scene/gltf_draco.hpp"

#include <draco/compression/decode.h>

#include "core/scene/gltf_accessor.hpp"

namespace pbr {

std::optional<DracoPrimitive> decodeDracoPrimitive(const GltfFile& file, const tinygltf::Primitive& primitive,
                                                   const std::string& field) {
  const auto extension = primitive.extensions.find("KHR_draco_mesh_compression");
  if (extension == primitive.extensions.end()) return std::nullopt;
  const std::string name = field + ".extensions.KHR_draco_mesh_compression";
  const tinygltf::Value& view = extension->second.Get("bufferView");
  const tinygltf::Value& ids = extension->second.Get("attributes");
  if (!view.IsInt()) file.fail(name + ".bufferView: must be a bufferView index");
  if (!ids.IsObject()) file.fail(name + ".attributes: must be an object of attribute ids");
  if (primitive.mode != TINYGLTF_MODE_TRIANGLES) file.fail(name + ": Draco meshes are triangle lists (mode 4)");
  const ByteSpan bytes = bufferViewBytes(file, view.GetNumberAsInt(), name + ".bufferView");

  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(bytes.data), bytes.size);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok()) file.fail(name + ": cannot decode the Draco data: " + decoded.status().error_msg_string());
  const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();

  DracoPrimitive out;
  out.vertices = mesh->num_points();
  for (const std::string& key : ids.Keys()) {
    const tinygltf::Value& id = ids.Get(key);
    const std::string where = name + ".attributes." + key;
    if (!id.IsInt() || id.GetNumberAsInt() < 0) file.fail(where + ": must be a Draco attribute id");
    const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(static_cast<uint32_t>(id.GetNumberAsInt()));
    if (!attribute) file.fail(where + ": the Draco data has no attribute " + std::to_string(id.GetNumberAsInt()));
    // The accessor the primitive names for the attribute gives the element type the values take.
    const auto accessor = primitive.attributes.find(key);
    if (accessor == primitive.attributes.end()) continue;  // compressed, but not an attribute of the primitive
    const auto& accessors = file.model.accessors;
    if (accessor->second < 0 || static_cast<size_t>(accessor->second) >= accessors.size()) {
      file.fail(field + ".attributes." + key + ": no accessor " + std::to_string(accessor->second));
    }
    const int components = componentsOf(accessors[static_cast<size_t>(accessor->second)].type);
    if (components == 0 || attribute->num_components() < components) {
      file.fail(where + ": Draco attribute of " + std::to_string(attribute->num_components()) +
                " components where its accessor needs " + std::to_string(components));
    }
    std::vector<float> values(out.vertices * static_cast<size_t>(components));
    std::vector<float> element(static_cast<size_t>(attribute->num_components()));
    for (uint32_t p = 0; p < mesh->num_points(); ++p) {
      if (!attribute->ConvertValue<float>(attribute->mapped_index(draco::PointIndex(p)), attribute->num_components(),
                                          element.data())) {
        file.fail(where + ": Draco values of a type that does not convert to numbers");
      }
      std::copy(element.begin(), element.begin() + components, values.begin() + p * components);
    }
    out.attributes[key] = std::move(values);
  }
  out.indices.reserve(size_t(mesh->num_faces()) * 3);
  for (uint32_t f = 0; f < mesh->num_faces(); ++f) {
    for (const draco::PointIndex& corner : mesh->face(draco::FaceIndex(f))) {
      if (corner.value() >= out.vertices) file.fail(name + ": a Draco face names a vertex past its points");
      out.indices.push_back(corner.value());
    }
  }
  return out;
}

}  // namespace pbr
