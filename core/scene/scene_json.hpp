#pragma once
#include <optional>
#include <string>

#include "core/scene/gltf_animation.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/uri_policy.hpp"

namespace pbr {

// Loads a scene file: JSON (the format of README "Scene files"), or a .gltf/.glb model on its own (see
// loadModelScene). Throws SceneError with one line naming the file, the JSON path (e.g. lights[3].radius) and
// what was expected. `lightCount`, when >= 0, replaces random_lights.count; a file without random_lights
// (or a model) rejects it. `policy` applies to the buffers and images of every glTF model loaded. A key the JSON
// reader never looks up is warned about on stderr, or with `strictKeys` refused (JsonField::reportUnknownKeys).
// `environment` is what a model, or a JSON scene placing glTF models, gets when the file has no "environment" (a
// note in Scene::notes says so); a JSON scene of shapes alone gets none. `spotShare`, when given, replaces
// random_lights.spot_share as `lightCount` does its count. `selection` applies to every glTF model the scene loads (the
// same scene index, animation name or index and time for each; appendGltf). The scene is checked by validateScene before it is
// returned.
Scene loadSceneFile(const std::string& path, int lightCount = -1, const UriPolicy& policy = {},
                    bool strictKeys = false, DefaultEnvironment environment = DefaultEnvironment::Sky,
                    std::optional<float> spotShare = std::nullopt, const GltfSelection& selection = {});

}  // namespace pbr
