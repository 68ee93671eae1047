#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/scene/gltf_animation.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/uri_policy.hpp"

namespace pbr {

struct RandomLightSpec {
  int count = 256;
  uint64_t seed = 1;
  glm::vec3 boundsMin{-5.0f, 0.2f, -5.0f};
  glm::vec3 boundsMax{5.0f, 2.5f, 5.0f};
  float radiusMin = 1.5f, radiusMax = 4.0f;
  float powerMin = 40.0f, powerMax = 200.0f;  // lumens
  // This share of the lights are spot lights aimed into the lower hemisphere, outer angles of 10-60 degrees and
  // inner ones up to 90% of them; the lights' other parameters are those of the same seed without spots.
  float spotShare = 0.0f;
};

// Seeded pseudo-random lights with saturated colours of random hue (max channel 1).
std::vector<PointLight> makeRandomLights(const RandomLightSpec& spec);

// What a user may change in a built-in scene from the command line.
struct SceneParams {
  std::optional<int> lights;          // light count (every scene)
  std::optional<float> viewAngleDeg;  // fresnel-floor: angle between the floor normal and the view direction
  std::optional<float> spotShare;     // scenes of random lights: the share of them that are spot lights
  UriPolicy uris;                     // scene files: where glTF buffers and images may be
  bool strictKeys = false;            // scene files: an unknown key is an error, not a warning (--strict)
  DefaultEnvironment defaultEnvironment = DefaultEnvironment::Sky;  // scene files: for glTF models given none
  GltfSelection gltfSelection;        // scene files: the scene, animation and time glTF models are drawn at
};

std::vector<std::string> builtinSceneNames();
bool isBuiltinScene(const std::string& name);

// The folder of the built-in scenes' files: PBR_SCENE_DIR in the environment, else the source tree's scenes/.
std::string builtinSceneDir();

// Loads scenes/<name>.json and applies `params` to it. Throws SceneError for an unknown name, a missing or
// malformed file, or a parameter out of range.
Scene makeBuiltinScene(const std::string& name, const SceneParams& params = {});

}  // namespace pbr
