#include "core/scene/gltf_deform.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "core/scene/gltf_accessor.hpp"

namespace pbr {

namespace {

// The morph displacement types: floats, or the integer forms KHR_mesh_quantization adds.
const std::initializer_list<int> kDisplacementTypes = {
    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT};

void requireCount(const GltfFile& file, const std::vector<float>& values, size_t width, size_t count,
                  const std::string& field) {
  if (values.size() != width * count) {
    file.fail(field + ": " + std::to_string(values.size() / width) + " elements where POSITION has " +
              std::to_string(count));
  }
  for (const float x : values) {
    if (!std::isfinite(x)) file.fail(field + ": values must be finite");
  }
}

}  // namespace

void applyMorphTargets(const GltfFile& file, const tinygltf::Primitive& primitive, const std::vector<float>& weights,
                       PrimitiveVertices& v, const std::string& field) {
  if (weights.size() > primitive.targets.size()) {
    file.fail(field + ".targets: " + std::to_string(weights.size()) + " weights for " +
              std::to_string(primitive.targets.size()) + " morph targets");
  }
  const size_t count = v.positions.size() / 3;
  for (size_t t = 0; t < weights.size(); ++t) {
    const float w = weights[t];
    if (!std::isfinite(w)) file.fail(field + ".targets: weight " + std::to_string(t) + " is not finite");
    if (w == 0.0f) continue;
    const std::string target = field + "." + gltfElement("targets", static_cast<int>(t));
    const auto& attributes = primitive.targets[t];
    const auto displace = [&](const char* name, std::vector<float>& values, size_t width) {
      const auto it = attributes.find(name);
      if (it == attributes.end() || values.empty()) return;
      const std::string where = target + "." + name;
      const std::vector<float> d = readFloatAccessor(file, it->second, TINYGLTF_TYPE_VEC3, kDisplacementTypes, where);
      requireCount(file, d, 3, count, where);
      for (size_t i = 0; i < count; ++i) {
        for (size_t c = 0; c < 3; ++c) values[width * i + c] += w * d[3 * i + c];
      }
    };
    displace("POSITION", v.positions, 3);
    displace("NORMAL", v.normals, 3);
    displace("TANGENT", v.tangents, 4);
  }
}

void applySkin(const GltfFile& file, const tinygltf::Primitive& primitive, const std::vector<glm::mat4>& jointMatrices,
               const AttributeReader& read, PrimitiveVertices& v, const std::string& field) {
  const size_t count = v.positions.size() / 3;
  // Up to two sets of four influences.
  std::vector<std::vector<float>> joints, weights;
  for (int set = 0; set < 2; ++set) {
    const auto j = primitive.attributes.find("JOINTS_" + std::to_string(set));
    const auto w = primitive.attributes.find("WEIGHTS_" + std::to_string(set));
    if (j == primitive.attributes.end() && w == primitive.attributes.end()) continue;
    const std::string jName = field + ".attributes.JOINTS_" + std::to_string(set);
    const std::string wName = field + ".attributes.WEIGHTS_" + std::to_string(set);
    if (j == primitive.attributes.end() || w == primitive.attributes.end()) {
      file.fail((j == primitive.attributes.end() ? jName : wName) + ": missing beside its " +
                (j == primitive.attributes.end() ? "WEIGHTS" : "JOINTS") + " set");
    }
    joints.push_back(read("JOINTS_" + std::to_string(set), TINYGLTF_TYPE_VEC4,
                          {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}));
    requireCount(file, joints.back(), 4, count, jName);
    weights.push_back(read("WEIGHTS_" + std::to_string(set), TINYGLTF_TYPE_VEC4,
                           {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}));
    requireCount(file, weights.back(), 4, count, wName);
  }
  if (joints.empty()) file.fail(field + ".attributes: a skinned mesh's primitive has no JOINTS_0 and WEIGHTS_0");
  for (size_t i = 0; i < count; ++i) {
    glm::mat4 m(0.0f);
    float total = 0.0f;
    for (size_t set = 0; set < joints.size(); ++set) {
      for (size_t k = 0; k < 4; ++k) {
        const float w = weights[set][4 * i + k];
        if (w == 0.0f) continue;
        if (w < 0.0f) file.fail(field + ".attributes.WEIGHTS_" + std::to_string(set) + ": negative weight");
        const size_t joint = static_cast<size_t>(joints[set][4 * i + k]);
        if (joint >= jointMatrices.size()) {
          file.fail(field + ".attributes.JOINTS_" + std::to_string(set) + ": joint " + std::to_string(joint) +
                    " at vertex " + std::to_string(i) + " is out of range (the skin has " +
                    std::to_string(jointMatrices.size()) + " joints)");
        }
        m += w * jointMatrices[joint];
        total += w;
      }
    }
    // Exporters round weights; they are meant to sum to 1. A vertex without any stays where its bind pose puts it.
    m = total > 0.0f ? m / total : glm::mat4(1.0f);
    const glm::vec3 p = glm::vec3(m * glm::vec4(v.positions[3 * i], v.positions[3 * i + 1], v.positions[3 * i + 2], 1));
    for (int c = 0; c < 3; ++c) v.positions[3 * i + static_cast<size_t>(c)] = p[c];
    const glm::mat3 linear(m);
    if (!v.normals.empty()) {
      // The cofactor matrix is the inverse transpose times the determinant: the same direction, and defined for a
      // joint scaled to nothing (a zero normal, which the loader then repairs from the faces).
      const glm::mat3 cofactor(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                               glm::cross(linear[0], linear[1]));
      glm::vec3 n = cofactor * glm::vec3(v.normals[3 * i], v.normals[3 * i + 1], v.normals[3 * i + 2]);
      n = glm::dot(n, n) > 0.0f ? glm::normalize(n) : n;
      for (int c = 0; c < 3; ++c) v.normals[3 * i + static_cast<size_t>(c)] = n[c];
    }
    if (!v.tangents.empty()) {
      const glm::vec3 t = linear * glm::vec3(v.tangents[4 * i], v.tangents[4 * i + 1], v.tangents[4 * i + 2]);
      for (int c = 0; c < 3; ++c) v.tangents[4 * i + static_cast<size_t>(c)] = t[c];
    }
  }
}

}  // namespace pbr
