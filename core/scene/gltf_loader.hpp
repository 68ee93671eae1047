#pragma once
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/scene/gltf_animation.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/uri_policy.hpp"

namespace pbr {

struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
};

// A KHR_lights_punctual point light without `range` gets the radius where its illuminance I/d^2 (I in candela
// times the brightest colour channel) falls to this value; the renderer's windowed attenuation ends it there.
constexpr float kGltfLightCutoffIlluminance = 0.01f;  // lux (lm/m^2)

// Appends a scene of a glTF 2.0 file (.gltf or .glb) to `scene`, the one `selection` names or else the file's
// default: every triangle primitive (TRIANGLES, strips and fans) becomes an object (its node's world transform
// pre-multiplied by `transform`), materials and the images they use are appended, and KHR_lights_punctual lights
// join scene.lights and scene.directionalLights. Accessors may be sparse. Nodes are posed as `selection` says (an
// animation sampled at a time, or the rest pose); morph targets are applied with the animation's, node's or mesh's weights and skinned meshes are skinned on the
// CPU, placed by their joints. Normals missing from a primitive are generated flat, tangents missing are generated
// per vertex. What is not drawn (points and lines, other scenes, used extensions outside kSupportedGltfExtensions)
// is named in one line on stderr per feature, as is each image drawn as a placeholder (missing or undecodable;
// refused under `policy.strict`). Returns the world bounds of the geometry appended. Throws
// SceneError("<path>: <field>: <what>") for a malformed file or a required extension outside
// kSupportedGltfExtensions, leaving `scene` as it was.
// `policy` says where the file's buffers and images may be (readGltfFile).
// A file loaded again into the same scene (by canonical path) adds its objects, placed by the new transform, and
// its lights, but shares the meshes, materials and textures the first load appended (Scene::gltfFiles).
Bounds appendGltf(Scene& scene, const std::string& path, const glm::mat4& transform = glm::mat4(1.0f),
                  const UriPolicy& policy = {}, const GltfSelection& selection = {});

// A playable load (GltfSelection::playable) of an animated file: what posePlayback needs to pose it again, and
// where its objects and lights lie in the scene. A node the animation scales to nothing keeps its objects (a zero
// transform) and lights (no power, radius 0), so that every moment has the same ones.
struct GltfPlayback {
  std::shared_ptr<const GltfFile> file;
  std::string key;  // of Scene::gltfFiles
  glm::mat4 transform{1.0f};
  GltfSelection selection;
  std::string animationName;  // the file's name for it, else "animations[N]"
  double duration = 0.0;      // seconds: its last keyframe's time
  size_t firstObject = 0, firstLight = 0, firstDirectionalLight = 0;
};

// Poses every playable glTF load of `scene` at `time` seconds of its animation, in place: objects' transforms,
// the meshes skins and morph targets deform, and lights. Returns the indices of the Scene::meshes rewritten.
// Throws SceneError as appendGltf does for a pose the file makes malformed (a translation beyond the limits).
std::vector<int> posePlayback(Scene& scene, double time);

}  // namespace pbr
