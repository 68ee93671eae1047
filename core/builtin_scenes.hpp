#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/scene.hpp"

namespace pbr {

struct RandomLightSpec {
  int count = 256;
  uint64_t seed = 1;
  glm::vec3 boundsMin{-5.0f, 0.2f, -5.0f};
  glm::vec3 boundsMax{5.0f, 2.5f, 5.0f};
  float radiusMin = 1.5f, radiusMax = 4.0f;
  float powerMin = 40.0f, powerMax = 200.0f;  // lumens
};

// Seeded pseudo-random lights with saturated colours of random hue (max channel 1).
std::vector<PointLight> makeRandomLights(const RandomLightSpec& spec);

std::vector<std::string> builtinSceneNames();

// Throws SceneError for an unknown name. `lightCount` replaces the scene's own light count where it has one.
Scene makeBuiltinScene(const std::string& name, int lightCount);

}  // namespace pbr
