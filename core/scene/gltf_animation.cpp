#include "core/scene/gltf_animation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/scene/gltf_accessor.hpp"

namespace pbr {

namespace {

// The keyframe pair around `time` in increasing `times`: the index k of the last keyframe at or before it and the
// fraction s in [0, 1] of the way to k + 1 (s 0 at or before the first keyframe, k the last after it).
struct Segment {
  size_t k;
  float s;
  float duration;  // t(k + 1) - t(k), 0 where the ends hold
};

Segment segmentAt(const std::vector<float>& times, double time) {
  if (time <= times.front()) return {0, 0.0f, 0.0f};
  if (time >= times.back()) return {times.size() - 1, 0.0f, 0.0f};
  const size_t k = static_cast<size_t>(std::upper_bound(times.begin(), times.end(), float(time)) - times.begin()) - 1;
  const float duration = times[k + 1] - times[k];
  return {k, duration > 0.0f ? static_cast<float>((time - times[k]) / duration) : 0.0f, duration};
}

// A sampler's output at `time`, `width` numbers an element (3 for translation and scale, 4 for rotation, the morph
// target count for weights).
std::vector<float> sample(const std::vector<float>& times, const std::vector<float>& values, size_t width,
                          const std::string& interpolation, double time, bool rotation) {
  const Segment seg = segmentAt(times, time);
  const bool cubic = interpolation == "CUBICSPLINE";
  // A CUBICSPLINE keyframe holds in-tangent, value, out-tangent.
  const auto value = [&](size_t k, size_t part) { return &values[(cubic ? 3 * k + part : k) * width]; };
  std::vector<float> out(width);
  const float* v0 = value(seg.k, 1);
  if (seg.duration == 0.0f || interpolation == "STEP") {
    std::copy(v0, v0 + width, out.begin());
    return out;
  }
  const float* v1 = value(seg.k + 1, 1);
  const float s = seg.s;
  if (cubic) {
    // glTF 2.0, Appendix C: p(s) = (2s^3 - 3s^2 + 1) v0 + (s^3 - 2s^2 + s) td b0 + (-2s^3 + 3s^2) v1
    //                             + (s^3 - s^2) td a1.
    const float* b0 = value(seg.k, 2);
    const float* a1 = value(seg.k + 1, 0);
    const float s2 = s * s, s3 = s2 * s, td = seg.duration;
    for (size_t i = 0; i < width; ++i) {
      out[i] = (2 * s3 - 3 * s2 + 1) * v0[i] + (s3 - 2 * s2 + s) * td * b0[i] + (-2 * s3 + 3 * s2) * v1[i] +
               (s3 - s2) * td * a1[i];
    }
  } else if (rotation) {
    const glm::quat q = glm::slerp(glm::quat(v0[3], v0[0], v0[1], v0[2]), glm::quat(v1[3], v1[0], v1[1], v1[2]), s);
    out = {q.x, q.y, q.z, q.w};
  } else {
    for (size_t i = 0; i < width; ++i) out[i] = v0[i] + s * (v1[i] - v0[i]);
  }
  return out;
}

}  // namespace

int findAnimation(const GltfFile& file, const GltfSelection& selection) {
  const auto& animations = file.model.animations;
  if (animations.empty()) {
    file.fail(std::string(selection.animation ? "--animation " + *selection.animation : "--time") +
              ": the file has no animations");
  }
  if (!selection.animation) return 0;
  for (size_t i = 0; i < animations.size(); ++i) {
    if (animations[i].name == *selection.animation) return static_cast<int>(i);
  }
  const std::string& choice = *selection.animation;
  char* end = nullptr;
  const long index = std::strtol(choice.c_str(), &end, 10);
  if (!choice.empty() && *end == '\0' && index >= 0 && static_cast<size_t>(index) < animations.size()) {
    return static_cast<int>(index);
  }
  std::string names;
  for (size_t i = 0; i < animations.size() && i < 8; ++i) {
    names += (i ? ", " : "") + (animations[i].name.empty() ? std::to_string(i) : "'" + animations[i].name + "'");
  }
  file.fail("--animation " + choice + ": no animation of that name or index (the file has " +
            std::to_string(animations.size()) + ": " + names + (animations.size() > 8 ? ", ..." : "") + ")");
}

std::vector<AnimatedNode> sampleAnimation(const GltfFile& file, int animation, double time) {
  const tinygltf::Animation& a = file.model.animations[static_cast<size_t>(animation)];
  const std::string name = gltfElement("animations", animation);
  std::vector<AnimatedNode> nodes(file.model.nodes.size());
  for (size_t c = 0; c < a.channels.size(); ++c) {
    const tinygltf::AnimationChannel& channel = a.channels[c];
    const std::string field = name + "." + gltfElement("channels", static_cast<int>(c));
    // A channel without a target node animates nothing this renderer draws (an extension's target).
    if (channel.target_node < 0) continue;
    if (static_cast<size_t>(channel.target_node) >= nodes.size()) {
      file.fail(field + ".target.node: no node " + std::to_string(channel.target_node));
    }
    if (channel.sampler < 0 || static_cast<size_t>(channel.sampler) >= a.samplers.size()) {
      file.fail(field + ".sampler: no sampler " + std::to_string(channel.sampler));
    }
    const tinygltf::AnimationSampler& sampler = a.samplers[static_cast<size_t>(channel.sampler)];
    const std::string samplerField = name + "." + gltfElement("samplers", channel.sampler);
    const std::string& interpolation = sampler.interpolation;
    if (interpolation != "LINEAR" && interpolation != "STEP" && interpolation != "CUBICSPLINE") {
      file.fail(samplerField + ".interpolation: '" + interpolation + "' is not LINEAR, STEP or CUBICSPLINE");
    }
    const std::vector<float> times =
        readFloatAccessor(file, sampler.input, TINYGLTF_TYPE_SCALAR, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                          samplerField + ".input");
    for (size_t i = 0; i < times.size(); ++i) {
      if (!std::isfinite(times[i]) || (i > 0 && !(times[i] > times[i - 1]))) {
        file.fail(samplerField + ".input: keyframe times must be finite and increasing (at keyframe " +
                  std::to_string(i) + ")");
      }
    }
    const std::string& path = channel.target_path;
    const tinygltf::Node& node = file.model.nodes[static_cast<size_t>(channel.target_node)];
    size_t width = 0;
    int type = TINYGLTF_TYPE_VEC3;
    if (path == "translation" || path == "scale") {
      width = 3;
    } else if (path == "rotation") {
      width = 4;
      type = TINYGLTF_TYPE_VEC4;
    } else if (path == "weights") {
      // As many weights a keyframe as the node's mesh has morph targets.
      const auto& meshes = file.model.meshes;
      if (node.mesh < 0 || static_cast<size_t>(node.mesh) >= meshes.size() ||
          meshes[static_cast<size_t>(node.mesh)].primitives.empty()) {
        file.fail(field + ".target: animates the weights of a node without a mesh");
      }
      width = meshes[static_cast<size_t>(node.mesh)].primitives.front().targets.size();
      type = TINYGLTF_TYPE_SCALAR;
    } else {
      file.fail(field + ".target.path: '" + path + "' is not translation, rotation, scale or weights");
    }
    if (!node.matrix.empty() && path != "weights") {
      file.fail(field + ".target.node: nodes[" + std::to_string(channel.target_node) +
                "] has a matrix, which animations may not target (glTF 2.0, 3.7.2)");
    }
    const std::vector<float> values =
        readFloatAccessor(file, sampler.output, type,
                          {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                          samplerField + ".output");
    const size_t perKey = width * (interpolation == "CUBICSPLINE" ? 3 : 1);
    if (width == 0 || times.empty() || values.size() != times.size() * perKey) {
      file.fail(samplerField + ".output: " + std::to_string(values.size()) + " numbers for " +
                std::to_string(times.size()) + " keyframes of " + std::to_string(perKey));
    }
    for (const float v : values) {
      if (!std::isfinite(v)) file.fail(samplerField + ".output: values must be finite");
    }
    const std::vector<float> v = sample(times, values, width, interpolation, time, path == "rotation");
    AnimatedNode& target = nodes[static_cast<size_t>(channel.target_node)];
    if (path == "translation") target.translation = glm::vec3(v[0], v[1], v[2]);
    if (path == "scale") target.scale = glm::vec3(v[0], v[1], v[2]);
    if (path == "weights") target.weights = v;
    if (path == "rotation") {
      const glm::quat q(v[3], v[0], v[1], v[2]);
      if (!(glm::length(q) > 1e-6f)) file.fail(samplerField + ".output: a rotation of length 0");
      target.rotation = glm::normalize(q);
    }
  }
  return nodes;
}

double animationDuration(const GltfFile& file, int animation) {
  const tinygltf::Animation& a = file.model.animations[static_cast<size_t>(animation)];
  const std::string name = gltfElement("animations", animation);
  double end = 0.0;
  for (size_t i = 0; i < a.samplers.size(); ++i) {
    const std::vector<float> times =
        readFloatAccessor(file, a.samplers[i].input, TINYGLTF_TYPE_SCALAR, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                          name + "." + gltfElement("samplers", static_cast<int>(i)) + ".input");
    if (!times.empty() && std::isfinite(times.back())) end = std::max(end, double(times.back()));
  }
  return end;
}

}  // namespace pbr
