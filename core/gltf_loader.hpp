#pragma once
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/scene.hpp"

namespace pbr {

struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
};

// Appends the default scene of a glTF 2.0 file (.gltf or .glb) to `scene`: every triangle primitive becomes an
// object (its node's world transform pre-multiplied by `transform`), materials and textures are appended, and
// KHR_lights_punctual point lights join scene.lights. Returns the world bounds of what was appended. Throws
// SceneError naming the file and what is wrong.
Bounds appendGltf(Scene& scene, const std::string& path, const glm::mat4& transform = glm::mat4(1.0f));

}  // namespace pbr
