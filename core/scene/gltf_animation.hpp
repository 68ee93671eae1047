#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "core/scene/gltf_file.hpp"

namespace pbr {

// What of a glTF file to draw: which of its scenes (`--gltf-scene`, default the file's `scene`) and which moment of
// its animations (`--animation`, `--time`). Without either of those, the rest pose: the nodes as the file places
// them (skins and morph weights applied, no animation).
struct GltfSelection {
  std::optional<int> scene;              // an index into the file's scenes
  std::optional<std::string> animation;  // a name or an index; absent with `time`: the file's first animation
  std::optional<double> time;            // seconds; absent with `animation`: 0
  // For the viewer, which plays the animation: the load keeps what posing it at other times needs (posePlayback):
  // the parsed file, and every node's objects and lights, those the animation scales to nothing drawn as nothing.
  bool playable = false;
  bool animated() const { return animation || time; }
};

// What one animation sets at one time: per node, the channels' translation, rotation, scale and morph weights (each
// absent where no channel targets it).
struct AnimatedNode {
  std::optional<glm::vec3> translation;
  std::optional<glm::quat> rotation;
  std::optional<glm::vec3> scale;
  std::optional<std::vector<float>> weights;
};

// The index of the animation `selection` names in `file` (its name, else an index); throws SceneError naming the
// choice and what the file has where it names none.
int findAnimation(const GltfFile& file, const GltfSelection& selection);

// Every channel of animation `animation` sampled at `time` seconds, by node index (file.model.nodes.size()
// entries). Before the first keyframe and after the last the ends hold. Interpolation as glTF 2.0 specifies it:
// STEP, LINEAR (rotations by spherical interpolation, the shorter way) and CUBICSPLINE (Hermite, with the output's
// in-tangent, value, out-tangent triples; rotations normalized after). Throws SceneError for malformed samplers.
std::vector<AnimatedNode> sampleAnimation(const GltfFile& file, int animation, double time);

// The time of animation `animation`'s last keyframe, in seconds (0 for one without channels).
double animationDuration(const GltfFile& file, int animation);

}  // namespace pbr
