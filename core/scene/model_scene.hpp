#pragma once
#include <string>
#include <vector>

#include "core/scene/camera.hpp"
#include "core/scene/gltf_loader.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

// A camera looking at the centre of `bounds` from the front, right and above (direction (0.5, 0.4, 1)), as close
// as lets the bounds' bounding sphere fit the vertical field of view with a margin; near and far enclose it.
Camera frameBounds(const Bounds& bounds, float fovYDeg);

// Key, fill and rim white lights around `bounds`, placed and powered in proportion to its size, so that the
// illuminance on the model is the same at any scale. For models that bring no lights.
std::vector<PointLight> defaultLightRig(const Bounds& bounds);

// A .gltf or .glb model alone: framed by frameBounds, a small ambient, the default rig when it has no lights, and
// the procedural sky unless `environment` is None. A file with lights gets the EV100 an incident-light meter reads
// at the model's centre (light_meter.hpp), ambient and sky scaled to it. What it adds so is said in Scene::notes.
// `selection` picks the glTF scene, animation and time the model is drawn at (appendGltf).
Scene loadModelScene(const std::string& path, const UriPolicy& policy = {},
                     DefaultEnvironment environment = DefaultEnvironment::Sky, const GltfSelection& selection = {});

}  // namespace pbr
