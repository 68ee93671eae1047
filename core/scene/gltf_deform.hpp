#pragma once
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/scene/gltf_file.hpp"

namespace pbr {

// One primitive's vertex attributes as read, 3 floats a position and a normal and 4 a tangent (normals and tangents
// empty where the primitive has none), deformed on the CPU before the mesh is built.
struct PrimitiveVertices {
  std::vector<float> positions, normals, tangents;
};

// Adds each morph target's POSITION, NORMAL and TANGENT displacements times its weight (glTF 2.0, 3.7.2.2); weights
// past the targets are refused, missing ones are 0. `field` names the primitive.
void applyMorphTargets(const GltfFile& file, const tinygltf::Primitive& primitive, const std::vector<float>& weights,
                       PrimitiveVertices& v, const std::string& field);

// Reads one of the primitive's attributes by name as floats (an accessor, or the primitive's decoded Draco data),
// checking its element type and component types.
using AttributeReader =
    std::function<std::vector<float>(const std::string& name, int type, std::initializer_list<int> componentTypes)>;

// Linear blend skinning (glTF 2.0, 3.7.3): each vertex moves by the weighted sum of the matrices of the joints
// JOINTS_n names (WEIGHTS_n, normalized to sum 1; both read through `read`), `jointMatrices` being each joint's
// world transform times its inverse bind matrix; normals by the sum's inverse transpose, tangents by the sum.
// Positions end in world space.
void applySkin(const GltfFile& file, const tinygltf::Primitive& primitive, const std::vector<glm::mat4>& jointMatrices,
               const AttributeReader& read, PrimitiveVertices& v, const std::string& field);

}  // namespace pbr
