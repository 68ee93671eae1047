#include "core/scene/gltf_loader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/scene/gltf_accessor.hpp"
#include "core/scene/gltf_animation.hpp"
#include "core/scene/gltf_deform.hpp"
#include "core/scene/gltf_draco.hpp"
#include "core/scene/gltf_file.hpp"
#include "core/scene/gltf_material.hpp"
#include "core/scene/mesh_tangent_space.hpp"

namespace pbr {

namespace {

constexpr float kPi = 3.14159265358979f;

// A transform that shrinks volume by more than this (a uniform scale of 1e-10) leaves nothing to see and a normal
// matrix that overflows; zero collapses the model entirely.
constexpr double kMinDeterminant = 1e-30;

// Where an orthographic camera with znear 0 gets its near plane, as a share of its far plane's distance.
constexpr float kOrthographicNearShare = 1e-4f;

// "1 animation", "2 animations".
std::string counted(size_t n, const std::string& noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

std::string number(double v) {
  std::ostringstream ss;
  ss << v;
  return ss.str();
}

double determinant3(const glm::mat4& m) {
  const auto e = [&](int c, int r) { return static_cast<double>(m[c][r]); };
  return e(0, 0) * (e(1, 1) * e(2, 2) - e(2, 1) * e(1, 2)) - e(1, 0) * (e(0, 1) * e(2, 2) - e(2, 1) * e(0, 2)) +
         e(2, 0) * (e(0, 1) * e(1, 2) - e(1, 1) * e(0, 2));
}

double largestMagnitude(const glm::vec3& v) {
  return std::max({std::fabs(double(v.x)), std::fabs(double(v.y)), std::fabs(double(v.z))});
}

void requireFinite(const GltfFile& file, const std::vector<float>& values, const std::string& field) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) file.fail(field + ": component " + std::to_string(i) + " is not a finite number");
  }
}

std::vector<double> checkedArray(const GltfFile& file, const std::vector<double>& v, size_t size,
                                 const std::string& field) {
  if (v.size() != size) {
    file.fail(field + ": must have " + std::to_string(size) + " numbers (got " + std::to_string(v.size()) + ")");
  }
  for (const double x : v) {
    if (!std::isfinite(x)) file.fail(field + ": must hold finite numbers");
  }
  return v;
}

// The property of a node that messages blame for its placement: the one that moves it, or scales it.
std::string placementField(const tinygltf::Node& node, const std::string& name, bool scaling) {
  if (!node.matrix.empty()) return name + ".matrix";
  if (scaling && !node.scale.empty()) return name + ".scale";
  if (!node.translation.empty()) return name + ".translation";
  return name + (node.scale.empty() ? "" : ".scale");
}

glm::mat4 localTransform(const GltfFile& file, const tinygltf::Node& node, const std::string& name) {
  if (!node.matrix.empty()) {
    const std::vector<double> m = checkedArray(file, node.matrix, 16, name + ".matrix");
    glm::mat4 out;
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) out[c][r] = static_cast<float>(m[static_cast<size_t>(c * 4 + r)]);  // column-major
    }
    // glTF node matrices are affine (decomposable into translation, rotation and scale).
    if (m[3] != 0.0 || m[7] != 0.0 || m[11] != 0.0 || m[15] != 1.0) {
      file.fail(name + ".matrix: its last row must be (0, 0, 0, 1), an affine transform");
    }
    if (!(std::fabs(determinant3(out)) >= kMinDeterminant)) {
      file.fail(name + ".matrix: is singular or nearly so (determinant " + number(determinant3(out)) + ")");
    }
    return out;
  }
  glm::mat4 out(1.0f);
  if (!node.translation.empty()) {
    const std::vector<double> t = checkedArray(file, node.translation, 3, name + ".translation");
    for (const double x : t) {
      if (std::fabs(x) > kMaxCoordinate) {
        file.fail(name + ".translation: " + number(x) + " is beyond the coordinate limit " + number(kMaxCoordinate));
      }
    }
    out = glm::translate(out, glm::vec3(t[0], t[1], t[2]));
  }
  if (!node.rotation.empty()) {
    const std::vector<double> q = checkedArray(file, node.rotation, 4, name + ".rotation");
    const glm::quat rotation(static_cast<float>(q[3]), static_cast<float>(q[0]), static_cast<float>(q[1]),
                             static_cast<float>(q[2]));
    if (!(glm::length(rotation) > 1e-6f)) file.fail(name + ".rotation: must be a unit quaternion");
    out *= glm::mat4_cast(glm::normalize(rotation));
  }
  if (!node.scale.empty()) {
    const std::vector<double> s = checkedArray(file, node.scale, 3, name + ".scale");
    if (!(std::fabs(s[0] * s[1] * s[2]) >= kMinDeterminant)) {
      file.fail(name + ".scale: [" + number(s[0]) + ", " + number(s[1]) + ", " + number(s[2]) +
                "] is zero or nearly so in some axis");
    }
    out = glm::scale(out, glm::vec3(s[0], s[1], s[2]));
  }
  return out;
}

// Whether any triangle of `mesh` spans an area: two edges whose angle has a sine above 1e-6, which float positions
// in one line or point never give.
bool coversArea(const MeshData& mesh) {
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const glm::dvec3 a(mesh.vertices[mesh.indices[i]].position), b(mesh.vertices[mesh.indices[i + 1]].position),
        c(mesh.vertices[mesh.indices[i + 2]].position);
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const double cross = glm::length(glm::cross(e1, e2)), scale = glm::length(e1) * glm::length(e2);
    if (cross > 1e-6 * scale && scale > 0.0) return true;
  }
  return false;
}

// Triangle lists from TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN index sequences, counter-clockwise.
std::vector<uint32_t> triangleList(const GltfFile& file, int mode, std::vector<uint32_t> indices,
                                   const std::string& field) {
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (indices.size() % 3 != 0) {
      file.fail(field + ": " + std::to_string(indices.size()) + " indices do not make whole triangles");
    }
    return indices;
  }
  std::vector<uint32_t> list;
  for (size_t i = 2; i < indices.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      list.insert(list.end(), {indices[0], indices[i - 1], indices[i]});
    } else if (i % 2 == 0) {
      list.insert(list.end(), {indices[i - 2], indices[i - 1], indices[i]});
    } else {
      // Every other strip triangle is wound the other way round.
      list.insert(list.end(), {indices[i - 1], indices[i - 2], indices[i]});
    }
  }
  return list;
}

// Walks the node tree once per load, so that every placement is checked, every object and light added and the
// bounds measured with this load's transform; meshes and materials come from `loaded` where an earlier load of
// the file converted them.
class Loader {
 public:
  Loader(const GltfFile& file, Scene& scene, LoadedGltf& loaded, const GltfSelection& selection)
      : file_(file), scene_(scene), loaded_(loaded), materials_(file, scene, loaded), selection_(selection) {}

  // The playable load `playback` again at this loader's selection's time, in place: the objects and lights it
  // placed, and the meshes it deforms (their indices added to `changed`).
  void pose(const GltfPlayback& playback, std::vector<int>& changed) {
    pose_ = &playback;
    changed_ = &changed;
    nextObject_ = playback.firstObject;
    nextLight_ = playback.firstLight;
    nextDirectional_ = playback.firstDirectionalLight;
    load(playback.transform);
  }

  Bounds load(const glm::mat4& transform) {
    const size_t placedLights = scene_.lights.size() + scene_.directionalLights.size();
    const size_t nodeCount = file_.model.nodes.size();
    placement_ = transform;
    if (selection_.animated()) {
      const int animation = findAnimation(file_, selection_);
      animated_ = sampleAnimation(file_, animation, selection_.time.value_or(0.0));
    }
    animated_.resize(nodeCount);
    // First every node's world transform, depth first, children in order (glTF node hierarchies are trees, so a
    // node met twice is malformed): a skinned mesh needs its joints' wherever they lie in the walk.
    std::vector<std::pair<int, glm::mat4>> stack;
    const std::vector<int> roots = rootNodes();
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, transform);
    worlds_.assign(nodeCount, std::nullopt);
    hidden_.assign(nodeCount, false);
    std::vector<int> order;
    // Every node's parent, -1 for a root: the walk below marks hidden subtrees by it, worldOf climbs it.
    parents_.assign(nodeCount, -1);
    for (size_t i = 0; i < nodeCount; ++i) {
      for (const int c : file_.model.nodes[i].children) {
        checkNode(c, gltfElement("nodes", static_cast<int>(i)) + ".children");
        parents_[static_cast<size_t>(c)] = static_cast<int>(i);
      }
    }
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      const std::string name = gltfElement("nodes", index);
      if (worlds_[static_cast<size_t>(index)]) file_.fail(name + ": reached twice (the node hierarchy is not a tree)");
      const tinygltf::Node& node = file_.model.nodes[static_cast<size_t>(index)];
      const glm::mat4 world = parent * posedTransform(index, name);
      const int up = parents_[static_cast<size_t>(index)];
      // An animation may scale a node to nothing, a common way to hide one: it and its children draw nothing.
      hidden_[static_cast<size_t>(index)] = (up >= 0 && hidden_[static_cast<size_t>(up)]) || scaledAway(index, world);
      if (!hidden_[static_cast<size_t>(index)]) checkWorld(world, node, name);
      worlds_[static_cast<size_t>(index)] = world;
      order.push_back(index);
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
        stack.emplace_back(*child, world);
      }
    }
    // Then what the nodes place, in the same order.
    for (const int index : order) {
      // A playable load keeps the objects and lights of hidden nodes, drawn as nothing.
      hiddenNode_ = hidden_[static_cast<size_t>(index)];
      if (hiddenNode_ && !selection_.playable) continue;
      const std::string name = gltfElement("nodes", index);
      const tinygltf::Node& node = file_.model.nodes[static_cast<size_t>(index)];
      const glm::mat4& world = *worlds_[static_cast<size_t>(index)];
      const auto instancing = node.extensions.find("EXT_mesh_gpu_instancing");
      if (node.mesh >= 0 && instancing != node.extensions.end()) {
        const std::string field = name + ".extensions.EXT_mesh_gpu_instancing";
        for (const glm::mat4& instance : instances(instancing->second, field)) {
          addMesh(node.mesh, world * instance, name + ".mesh", field, nullptr);
        }
      } else if (node.mesh >= 0) {
        const std::optional<Deformation> deformation = deformationOf(index, name);
        // A skinned mesh is placed by its joints, which the skinning applies: its own node's transform is not
        // (glTF 2.0, 3.7.3.3).
        addMesh(node.mesh, deformation && !deformation->joints.empty() ? glm::mat4(1.0f) : world, name + ".mesh",
                placementField(node, name, false), deformation ? &*deformation : nullptr);
      }
      const auto light = node.extensions.find("KHR_lights_punctual");
      if (light != node.extensions.end()) addLight(light->second, world, name + ".extensions.KHR_lights_punctual");
      if (node.camera >= 0 && !pose_ && !hiddenNode_) addCamera(node.camera, world, name + ".camera");
    }
    hiddenNode_ = false;
    if (pose_) return bounds_;
    const bool placed = scene_.lights.size() + scene_.directionalLights.size() > placedLights;
    scene_.gltfPlacedLights = scene_.gltfPlacedLights || placed;
    if (!file_.model.lights.empty() && !placed) {
      file_.warn("extensions.KHR_lights_punctual.lights: " + counted(file_.model.lights.size(), "light") +
                 ", none placed by a node of the scene: not drawn");
    }
    warnUndrawnFeatures();
    // glTF leaves zfar out for an infinite far plane; the depth slices need a finite one, and nothing of the file
    // lies beyond its bounds, so the far plane is put just past their farthest corner.
    for (auto& [camera, infinite] : cameras_) {
      if (infinite) camera.farPlane = std::max(farthestCorner(camera.position) * 1.01f, 2.0f * camera.nearPlane);
      scene_.cameras.push_back(camera);
    }
    return bounds_;
  }

 private:
  // What the file holds that is not drawn, one line per feature: never dropped without a word; and, as a note,
  // animations left at rest.
  void warnUndrawnFeatures() const {
    const tinygltf::Model& m = file_.model;
    if (!m.animations.empty() && !selection_.animated()) {
      scene_.notes.push_back(gltfFileName() + " has " + counted(m.animations.size(), "animation") +
                             ": drawn at rest (--animation NAME|INDEX and --time SECONDS pose it)");
    }
    if (m.scenes.size() > 1 && !selection_.scene) {
      scene_.notes.push_back(gltfFileName() + " has " + counted(m.scenes.size(), "scene") + ": scene " +
                             std::to_string(drawnScene()) + " is drawn (--gltf-scene N draws another)");
    }
  }

  float farthestCorner(const glm::vec3& from) const {
    float farthest = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p(corner & 1 ? bounds_.max.x : bounds_.min.x, corner & 2 ? bounds_.max.y : bounds_.min.y,
                        corner & 4 ? bounds_.max.z : bounds_.min.z);
      farthest = std::max(farthest, glm::length(p - from));
    }
    return farthest;
  }

  // EXT_mesh_gpu_instancing: one local transform per instance, translation x rotation x scale, each attribute
  // optional and all of one count; the node's world transform applies after it. An instance scaled to nothing
  // (a way to hide one) draws nothing.
  std::vector<glm::mat4> instances(const tinygltf::Value& extension, const std::string& field) const {
    const tinygltf::Value& attributes = extension.Get("attributes");
    if (!attributes.IsObject()) file_.fail(field + ".attributes: must be an object");
    const auto read = [&](const char* name, int type, std::initializer_list<int> componentTypes) {
      const tinygltf::Value& index = attributes.Get(name);
      if (!attributes.Has(name)) return std::vector<float>();
      if (!index.IsInt()) file_.fail(field + ".attributes." + name + ": must be an accessor index");
      const std::string where = field + ".attributes." + name;
      std::vector<float> values = readFloatAccessor(file_, index.GetNumberAsInt(), type, componentTypes, where);
      requireFinite(file_, values, where);
      return values;
    };
    const std::vector<float> t = read("TRANSLATION", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT});
    const std::vector<float> r =
        read("ROTATION", TINYGLTF_TYPE_VEC4,
             {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT});
    const std::vector<float> s = read("SCALE", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT});
    const size_t count = !t.empty() ? t.size() / 3 : !r.empty() ? r.size() / 4 : s.size() / 3;
    if (t.empty() && r.empty() && s.empty()) file_.fail(field + ".attributes: has no TRANSLATION, ROTATION or SCALE");
    if ((!t.empty() && t.size() / 3 != count) || (!r.empty() && r.size() / 4 != count) ||
        (!s.empty() && s.size() / 3 != count)) {
      file_.fail(field + ".attributes: TRANSLATION, ROTATION and SCALE must have as many elements as each other");
    }
    std::vector<glm::mat4> out;
    out.reserve(count);
    for (size_t i = 0; i < count; ++i) {
      glm::mat4 m(1.0f);
      if (!t.empty()) m = glm::translate(m, glm::vec3(t[3 * i], t[3 * i + 1], t[3 * i + 2]));
      if (!r.empty()) {
        const glm::quat q(r[4 * i + 3], r[4 * i], r[4 * i + 1], r[4 * i + 2]);
        if (!(glm::length(q) > 1e-6f)) file_.fail(field + ".attributes.ROTATION: element " + std::to_string(i) +
                                                  " is not a unit quaternion");
        m *= glm::mat4_cast(glm::normalize(q));
      }
      if (!s.empty()) m = glm::scale(m, glm::vec3(s[3 * i], s[3 * i + 1], s[3 * i + 2]));
      if (std::fabs(determinant3(m)) < kMinDeterminant) continue;
      out.push_back(m);
    }
    return out;
  }

  // A camera looks down its node's -Z with +Y up; the frame's own aspect ratio replaces the file's (a perspective
  // camera's aspectRatio, an orthographic one's xmag: its ymag sets the height, the frame's aspect the width).
  void addCamera(int index, const glm::mat4& world, const std::string& field) {
    const auto& cameras = file_.model.cameras;
    if (static_cast<size_t>(index) >= cameras.size()) {
      file_.fail(field + ": not the index of one of the file's " + std::to_string(cameras.size()) + " cameras");
    }
    const tinygltf::Camera& c = cameras[static_cast<size_t>(index)];
    const std::string name = gltfElement("cameras", index);
    Camera camera;
    bool infinite = false;
    if (c.type == "perspective") {
      const tinygltf::PerspectiveCamera& p = c.perspective;
      // The renderer draws vertical fields of view of 1 to 179 degrees.
      if (!(p.yfov >= glm::radians(1.0) && p.yfov <= glm::radians(179.0))) {
        file_.fail(name + ".perspective.yfov: must be in [" + number(glm::radians(1.0)) + ", " +
                   number(glm::radians(179.0)) + "] radians, 1 to 179 degrees (got " + number(p.yfov) + ")");
      }
      if (!(p.znear > 0.0 && p.znear <= kMaxCoordinate)) file_.fail(name + ".perspective.znear: must be > 0");
      if (p.zfar != 0.0 && !(p.zfar > p.znear && p.zfar <= kMaxCoordinate)) {
        file_.fail(name + ".perspective.zfar: must be greater than znear");
      }
      camera.fovYDeg = static_cast<float>(glm::degrees(p.yfov));
      camera.nearPlane = static_cast<float>(p.znear);
      camera.farPlane = static_cast<float>(p.zfar);  // 0: tinygltf's absent zfar, set from the bounds in load()
      infinite = p.zfar == 0.0;
    } else if (c.type == "orthographic") {
      readOrthographic(c.orthographic, name + ".orthographic", camera);
    } else {
      file_.warn(name + ": " + c.type + " cameras are not supported, skipped");
      return;
    }
    camera.position = glm::vec3(world[3]);
    const glm::vec3 forward = glm::normalize(glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f));
    camera.target = camera.position + forward;
    camera.up = glm::normalize(glm::mat3(world) * glm::vec3(0.0f, 1.0f, 0.0f));
    cameras_.push_back({camera, infinite});
  }

  // The specification forbids xmag and ymag of 0 and advises against negative ones (which some viewers read as a
  // mirrored image): their magnitude is used, with a warning. A znear of 0 is valid, but the depth slices are
  // spaced by the logarithm of depth: the near plane then lies at 1e-4 of zfar, said in a note.
  void readOrthographic(const tinygltf::OrthographicCamera& o, const std::string& owner, Camera& camera) const {
    for (const auto& [key, mag] : {std::pair<const char*, double>{"xmag", o.xmag}, {"ymag", o.ymag}}) {
      // The renderer draws views of 1e-6 to 1e6 metres (validateScene's orthographic half height).
      if (!(std::fabs(mag) >= 1e-6 && std::fabs(mag) <= 1e6)) {
        file_.fail(owner + "." + key + ": must be a magnification of 1e-6 to 1e6 metres, not 0 (got " + number(mag) +
                   ")");
      }
      if (mag < 0.0) {
        if (file_.policy.strict) file_.fail(owner + "." + key + ": must not be negative (got " + number(mag) + ")");
        file_.warn(owner + "." + key + ": " + number(mag) + " is negative; its magnitude is used, unmirrored "
                   "(--strict refuses it)");
      }
    }
    if (!(o.znear >= 0.0 && o.znear <= kMaxCoordinate)) file_.fail(owner + ".znear: must be >= 0");
    if (!(o.zfar > o.znear && o.zfar <= kMaxCoordinate)) file_.fail(owner + ".zfar: must be greater than znear");
    camera.orthographic = true;
    camera.orthoHalfHeight = static_cast<float>(std::fabs(o.ymag));
    camera.farPlane = static_cast<float>(o.zfar);
    camera.nearPlane = static_cast<float>(o.znear);
    if (o.znear == 0.0) {
      camera.nearPlane = camera.farPlane * kOrthographicNearShare;
      scene_.notes.push_back(gltfFileName() + ": " + owner + ".znear: 0, the near plane set at " +
                             number(camera.nearPlane) + " (1e-4 of zfar): the depth slices need one above 0");
    }
  }

  // A node's transform combined with its parents' may still overflow or collapse; the node is named, not the
  // camera or lights computed from it later.
  void checkWorld(const glm::mat4& world, const tinygltf::Node& node, const std::string& name) const {
    const double det = determinant3(world);
    if (!std::isfinite(det) || std::fabs(det) < kMinDeterminant) {
      file_.fail(placementField(node, name, true) + ": with its parents' transforms, scales the node to " +
                 (std::isfinite(det) ? "nothing" : "infinity") + " (determinant " + number(det) + ")");
    }
    const glm::vec3 origin(world[3]);
    if (!(largestMagnitude(origin) <= kMaxCoordinate)) {
      file_.fail(placementField(node, name, false) + ": with its parents' transforms, places the node at " +
                 number(largestMagnitude(origin)) + " from the origin, beyond the coordinate limit " +
                 number(kMaxCoordinate));
    }
  }

  void checkNode(int index, const std::string& field) const {
    if (index < 0 || static_cast<size_t>(index) >= file_.model.nodes.size()) {
      file_.fail(field + ": no node " + std::to_string(index));
    }
  }

  // The scene drawn: the one chosen, else the file's default, else the first; -1 for a file without scenes.
  int drawnScene() const {
    const tinygltf::Model& m = file_.model;
    if (selection_.scene) return *selection_.scene;
    return m.defaultScene >= 0 ? m.defaultScene : m.scenes.empty() ? -1 : 0;
  }

  // The drawn scene's roots; a file without scenes shows every node that is no other node's child.
  std::vector<int> rootNodes() const {
    const tinygltf::Model& m = file_.model;
    const int scene = drawnScene();
    if (selection_.scene && scene >= static_cast<int>(m.scenes.size())) {
      file_.fail("--gltf-scene " + std::to_string(scene) + ": the file has " + counted(m.scenes.size(), "scene"));
    }
    if (scene >= static_cast<int>(m.scenes.size())) file_.fail("scene: no scene " + std::to_string(scene));
    if (scene >= 0) {
      const std::string field = gltfElement("scenes", scene) + ".nodes";
      for (const int n : m.scenes[static_cast<size_t>(scene)].nodes) checkNode(n, field);
      return m.scenes[static_cast<size_t>(scene)].nodes;
    }
    std::vector<bool> child(m.nodes.size(), false);
    for (size_t i = 0; i < m.nodes.size(); ++i) {
      for (const int c : m.nodes[i].children) {
        checkNode(c, gltfElement("nodes", static_cast<int>(i)) + ".children");
        child[static_cast<size_t>(c)] = true;
      }
    }
    std::vector<int> roots;
    for (size_t i = 0; i < m.nodes.size(); ++i) {
      if (!child[i]) roots.push_back(static_cast<int>(i));
    }
    return roots;
  }

  // Morph weights and skinning joint matrices for one node's mesh (empty where it has none).
  struct Deformation {
    std::vector<float> weights;
    std::vector<glm::mat4> joints;
  };

  // A node's local transform, with what the chosen animation sets in place of the node's own translation,
  // rotation and scale (animations may not target nodes given as a matrix: sampleAnimation refuses them).
  glm::mat4 posedTransform(int index, const std::string& name) const {
    const tinygltf::Node& node = file_.model.nodes[static_cast<size_t>(index)];
    const glm::mat4 still = localTransform(file_, node, name);  // checks the node's own values too
    const AnimatedNode& a = animated_[static_cast<size_t>(index)];
    if (!a.translation && !a.rotation && !a.scale) return still;
    const auto vec3Of = [](const std::vector<double>& v, float fallback) {
      return v.size() == 3 ? glm::vec3(v[0], v[1], v[2]) : glm::vec3(fallback);
    };
    const glm::vec3 t = a.translation.value_or(vec3Of(node.translation, 0.0f));
    const glm::quat r = a.rotation.value_or(
        node.rotation.size() == 4
            ? glm::normalize(glm::quat(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]),
                                       float(node.rotation[2])))
            : glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
    const glm::vec3 s = a.scale.value_or(vec3Of(node.scale, 1.0f));
    for (int c = 0; c < 3; ++c) {
      if (std::fabs(t[c]) > kMaxCoordinate) {
        file_.fail(name + ": animated to a translation beyond the coordinate limit " + number(kMaxCoordinate));
      }
    }
    return glm::scale(glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r), s);
  }

  // Whether the animation scales node `index` to nothing at this time.
  bool scaledAway(int index, const glm::mat4& world) const {
    return animated_[static_cast<size_t>(index)].scale && !(std::fabs(determinant3(world)) >= kMinDeterminant);
  }

  // The world transform of any node: from the walk for the scene's nodes, else up its parents' chain (a skin's
  // joints may lie outside the scene); the chain's root is placed as the scene's roots are.
  glm::mat4 worldOf(int index) {
    if (worlds_[static_cast<size_t>(index)]) return *worlds_[static_cast<size_t>(index)];
    glm::mat4 world(1.0f);
    size_t steps = 0;
    for (int n = index; n >= 0; n = parents_[static_cast<size_t>(n)]) {
      if (++steps > parents_.size()) file_.fail(gltfElement("nodes", index) + ": its parents form a cycle");
      world = posedTransform(n, gltfElement("nodes", n)) * world;
    }
    world = placement_ * world;
    worlds_[static_cast<size_t>(index)] = world;
    return world;
  }

  // What deforms node `index`'s mesh: its morph weights (the animation's, else the node's, else the mesh's, when
  // one is non-zero and the mesh has targets) and, for a skinned node, each joint's world transform times its
  // inverse bind matrix. Nothing where neither applies.
  std::optional<Deformation> deformationOf(int index, const std::string& name) {
    const tinygltf::Node& node = file_.model.nodes[static_cast<size_t>(index)];
    if (static_cast<size_t>(node.mesh) >= file_.model.meshes.size()) return std::nullopt;  // addMesh says so
    const tinygltf::Mesh& mesh = file_.model.meshes[static_cast<size_t>(node.mesh)];
    Deformation d;
    const AnimatedNode& a = animated_[static_cast<size_t>(index)];
    if (a.weights) {
      d.weights = *a.weights;
    } else {
      for (const double w : !node.weights.empty() ? node.weights : mesh.weights) d.weights.push_back(float(w));
    }
    const bool targets = std::any_of(mesh.primitives.begin(), mesh.primitives.end(),
                                     [](const tinygltf::Primitive& p) { return !p.targets.empty(); });
    // A playable load deforms a mesh with targets at every moment, so that it has a mesh of its own to rewrite.
    if (!targets ||
        (!selection_.playable && std::all_of(d.weights.begin(), d.weights.end(), [](float w) { return w == 0.0f; }))) {
      d.weights.clear();
    }
    if (node.skin >= 0) d.joints = jointMatrices(node.skin, name + ".skin");
    if (d.weights.empty() && d.joints.empty() && !(selection_.playable && targets)) return std::nullopt;
    return d;
  }

  std::vector<glm::mat4> jointMatrices(int skinIndex, const std::string& field) {
    const auto& skins = file_.model.skins;
    if (static_cast<size_t>(skinIndex) >= skins.size()) file_.fail(field + ": no skin " + std::to_string(skinIndex));
    const tinygltf::Skin& skin = skins[static_cast<size_t>(skinIndex)];
    const std::string name = gltfElement("skins", skinIndex);
    if (skin.joints.empty()) file_.fail(name + ".joints: a skin needs at least one joint");
    std::vector<float> inverseBind;
    if (skin.inverseBindMatrices >= 0) {
      inverseBind = readFloatAccessor(file_, skin.inverseBindMatrices, TINYGLTF_TYPE_MAT4,
                                      {TINYGLTF_COMPONENT_TYPE_FLOAT}, name + ".inverseBindMatrices");
      requireFinite(file_, inverseBind, name + ".inverseBindMatrices");
      if (inverseBind.size() < 16 * skin.joints.size()) {
        file_.fail(name + ".inverseBindMatrices: " + std::to_string(inverseBind.size() / 16) + " matrices for " +
                   std::to_string(skin.joints.size()) + " joints");
      }
    }
    std::vector<glm::mat4> out;
    for (size_t j = 0; j < skin.joints.size(); ++j) {
      checkNode(skin.joints[j], name + ".joints");
      glm::mat4 ibm(1.0f);
      for (int c = 0; c < 4 && !inverseBind.empty(); ++c) {
        for (int r = 0; r < 4; ++r) ibm[c][r] = inverseBind[16 * j + static_cast<size_t>(4 * c + r)];  // column-major
      }
      out.push_back(worldOf(skin.joints[j]) * ibm);
    }
    return out;
  }

  std::string gltfFileName() const { return std::filesystem::path(file_.path).filename().string(); }

  void addMesh(int index, const glm::mat4& world, const std::string& field, const std::string& placement,
               const Deformation* deformation) {
    if (static_cast<size_t>(index) >= file_.model.meshes.size()) {
      file_.fail(field + ": no mesh " + std::to_string(index));
    }
    const tinygltf::Mesh& mesh = file_.model.meshes[static_cast<size_t>(index)];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const int sceneMesh = pose_ && deformation ? deformedAgain(index, static_cast<int>(p), *deformation)
                                                 : primitiveMesh(index, static_cast<int>(p), deformation);
      if (sceneMesh < 0) continue;
      // Scaled to nothing: the primitive's triangles collapse to a point, which rasterizes no fragment.
      const glm::mat4 placed = hiddenNode_ ? glm::mat4(0.0f) : world;
      if (pose_) {
        scene_.objects.at(nextObject_++).transform = placed;
      } else {
        const std::string material =
            gltfElement("meshes", index) + "." + gltfElement("primitives", static_cast<int>(p)) + ".material";
        scene_.objects.push_back(
            {Shape::Mesh, sceneMesh, placed, materials_.get(mesh.primitives[p].material, material)});
      }
      if (hiddenNode_) continue;
      for (const Vertex& v : scene_.meshes[static_cast<size_t>(sceneMesh)].vertices) {
        const glm::vec3 w = glm::vec3(world * glm::vec4(v.position, 1.0f));
        if (!(largestMagnitude(w) <= kMaxCoordinate)) {
          file_.fail(placement + ": places " + gltfElement("meshes", index) + " at " + number(largestMagnitude(w)) +
                     " from the origin, beyond the coordinate limit " + number(kMaxCoordinate));
        }
        bounds_.min = empty_ ? w : glm::min(bounds_.min, w);
        bounds_.max = empty_ ? w : glm::max(bounds_.max, w);
        empty_ = false;
      }
    }
  }

  // Posing a playable load: the deformed primitive's mesh rewritten in place, the one its object at the cursor
  // draws; -1 where the load drew none (the same primitives as then: what is drawn does not depend on the pose).
  int deformedAgain(int meshIndex, int primitiveIndex, const Deformation& deformation) {
    const tinygltf::Primitive& prim =
        file_.model.meshes[static_cast<size_t>(meshIndex)].primitives[static_cast<size_t>(primitiveIndex)];
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        prim.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      return -1;
    }
    const std::string field = gltfElement("meshes", meshIndex) + "." + gltfElement("primitives", primitiveIndex);
    MeshData mesh = readPrimitive(prim, field, readsTexCoord1(materials_.get(prim.material, field + ".material")),
                                  &deformation);
    if (mesh.indices.empty()) return -1;
    const int target = scene_.objects.at(nextObject_).mesh;
    scene_.meshes.at(static_cast<size_t>(target)) = std::move(mesh);
    changed_->push_back(target);
    return target;
  }

  // A float POSITION accessor's min and max, which the specification requires, against the positions read: the
  // renderer measures its own bounds, but viewers that cull by the declared ones leave such a mesh out, so a pair
  // that does not hold the data (beyond a thousandth of its extent: Draco's quantization) is named in a warning.
  void checkDeclaredBounds(int accessor, const std::vector<float>& positions, const std::string& field) const {
    const tinygltf::Accessor& a = file_.model.accessors.at(static_cast<size_t>(accessor));
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.minValues.size() != 3 || a.maxValues.size() != 3 ||
        positions.empty()) {
      return;
    }
    glm::dvec3 lo(positions[0], positions[1], positions[2]), hi = lo;
    for (size_t i = 0; i + 2 < positions.size(); i += 3) {
      const glm::dvec3 p(positions[i], positions[i + 1], positions[i + 2]);
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    const glm::dvec3 declaredLo(a.minValues[0], a.minValues[1], a.minValues[2]);
    const glm::dvec3 declaredHi(a.maxValues[0], a.maxValues[1], a.maxValues[2]);
    const double tolerance = 1e-3 * std::max({glm::length(hi - lo), glm::length(hi), glm::length(lo)}) + 1e-6;
    if (glm::all(glm::lessThanEqual(glm::abs(declaredLo - lo), glm::dvec3(tolerance))) &&
        glm::all(glm::lessThanEqual(glm::abs(declaredHi - hi), glm::dvec3(tolerance)))) {
      return;
    }
    const auto text = [](const glm::dvec3& v) {
      return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]";
    };
    if (file_.policy.strict) {
      file_.fail(gltfElement("accessors", accessor) + ".min/max: " + text(declaredLo) + " to " + text(declaredHi) +
                 " do not hold the data");
    }
    file_.warn(gltfElement("accessors", accessor) + ".min/max (" + field + "): " + text(declaredLo) + " to " +
               text(declaredHi) + " do not hold the positions, " + text(lo) + " to " + text(hi) +
               ", which are drawn (--strict refuses it)");
  }

  // Index into Scene::meshes of a primitive, converted once however many nodes and loads use it (a deformed one
  // for each node that deforms it); -1 for what is not drawn.
  int primitiveMesh(int meshIndex, int primitiveIndex, const Deformation* deformation) {
    const auto cached = loaded_.meshes.find({meshIndex, primitiveIndex});
    if (cached != loaded_.meshes.end() && !deformation) return cached->second;
    const tinygltf::Primitive& prim =
        file_.model.meshes[static_cast<size_t>(meshIndex)].primitives[static_cast<size_t>(primitiveIndex)];
    const std::string field = gltfElement("meshes", meshIndex) + "." + gltfElement("primitives", primitiveIndex);
    int result = -1;
    if (prim.mode == TINYGLTF_MODE_TRIANGLES || prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
        prim.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      // A primitive has one material: the second UV set is read only where one of its maps reads it.
      const bool uv1 = readsTexCoord1(materials_.get(prim.material, field + ".material"));
      MeshData mesh = readPrimitive(prim, field, uv1, deformation);
      if (!mesh.indices.empty()) {
        scene_.meshes.push_back(std::move(mesh));
        result = static_cast<int>(scene_.meshes.size()) - 1;
      }
    } else {
      file_.warn(field + ": mode " + std::to_string(prim.mode) + " (points or lines) is not drawn");
    }
    if (!deformation) loaded_.meshes.emplace(std::make_pair(meshIndex, primitiveIndex), result);
    return result;
  }

  MeshData readPrimitive(const tinygltf::Primitive& prim, const std::string& field, bool readUv1,
                         const Deformation* deformation) const {
    const auto attribute = [&](const char* name) {
      const auto it = prim.attributes.find(name);
      return it == prim.attributes.end() ? -1 : it->second;
    };
    // KHR_draco_mesh_compression: the compressed attributes and the indices come from the decoded Draco mesh.
    const std::optional<DracoPrimitive> draco = decodeDracoPrimitive(file_, prim, field);
    const AttributeReader readAttribute = [&](const std::string& name, int type,
                                              std::initializer_list<int> componentTypes) {
      const std::string where = field + ".attributes." + name;
      if (draco && draco->attributes.count(name)) return draco->attributes.at(name);
      const auto it = prim.attributes.find(name);
      return readFloatAccessor(file_, it == prim.attributes.end() ? -1 : it->second, type, componentTypes, where);
    };
    const auto read = [&](const char* name, int type, std::initializer_list<int> componentTypes, size_t count) {
      const std::string where = field + ".attributes." + name;
      std::vector<float> values = readAttribute(name, type, componentTypes);
      const size_t n = values.size() / static_cast<size_t>(type);
      if (count && n != count) {
        file_.fail(where + ": " + std::to_string(n) + " elements where POSITION has " + std::to_string(count));
      }
      requireFinite(file_, values, where);
      return values;
    };
    // KHR_mesh_quantization: positions and texture coordinates may be any 8- or 16-bit integers, normalized or
    // not (the node's transform scales them back), normals and tangents normalized 8- or 16-bit integers.
    const auto& used = file_.model.extensionsUsed;
    const bool quantized = std::find(used.begin(), used.end(), "KHR_mesh_quantization") != used.end();
    constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT, kByte = TINYGLTF_COMPONENT_TYPE_BYTE,
                  kUbyte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, kShort = TINYGLTF_COMPONENT_TYPE_SHORT,
                  kUshort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    const std::initializer_list<int> anyPosition = {kFloat, kByte, kUbyte, kShort, kUshort}, floatOnly = {kFloat},
                                     signedUnit = {kFloat, kByte, kShort}, coreUv = {kFloat, kUbyte, kUshort};
    if (attribute("POSITION") < 0) file_.fail(field + ".attributes: no POSITION");
    PrimitiveVertices attributes;
    std::vector<float>& positions = attributes.positions;
    positions = read("POSITION", TINYGLTF_TYPE_VEC3, quantized ? anyPosition : floatOnly, 0);
    const size_t count = positions.size() / 3;
    for (const float p : positions) {
      if (std::fabs(p) > kMaxCoordinate) {
        file_.fail(field + ".attributes.POSITION: coordinate " + number(p) + " is beyond the limit " +
                   number(kMaxCoordinate));
      }
    }
    // The file's own checks, made once at load: posing it again at other times reads the same accessors.
    if (!pose_) checkDeclaredBounds(attribute("POSITION"), positions, field + ".attributes.POSITION");
    const bool hasNormals = attribute("NORMAL") >= 0;
    // glTF: without normals, tangents from the file are ignored too.
    const bool hasTangents = hasNormals && attribute("TANGENT") >= 0;
    std::vector<float>& normals = attributes.normals;
    std::vector<float>& tangents = attributes.tangents;
    if (hasNormals) normals = read("NORMAL", TINYGLTF_TYPE_VEC3, quantized ? signedUnit : floatOnly, count);
    if (hasTangents) tangents = read("TANGENT", TINYGLTF_TYPE_VEC4, quantized ? signedUnit : floatOnly, count);
    // Morph targets first, then the skin (glTF 2.0, 3.7.3.1).
    if (deformation && !deformation->weights.empty()) {
      applyMorphTargets(file_, prim, deformation->weights, attributes, field);
    }
    if (deformation && !deformation->joints.empty()) {
      applySkin(file_, prim, deformation->joints, readAttribute, attributes, field);
    }
    const std::vector<float> uvs =
        attribute("TEXCOORD_0") >= 0 ? read("TEXCOORD_0", TINYGLTF_TYPE_VEC2, quantized ? anyPosition : coreUv, count)
                                     : std::vector<float>();
    if (readUv1 && attribute("TEXCOORD_1") < 0) {
      file_.warn(field + ".attributes: its material reads TEXCOORD_1, which the primitive lacks: TEXCOORD_0 is used");
    }
    const std::vector<float> uv1 =
        readUv1 && attribute("TEXCOORD_1") >= 0
            ? read("TEXCOORD_1", TINYGLTF_TYPE_VEC2, quantized ? anyPosition : coreUv, count)
            : std::vector<float>();
    // COLOR_0: RGB or RGBA, float or normalized unsigned integers (alpha 1 for RGB).
    const int colorAccessor = attribute("COLOR_0");
    const auto& accessors = file_.model.accessors;
    const int colorType = colorAccessor >= 0 && static_cast<size_t>(colorAccessor) < accessors.size() &&
                                  accessors[static_cast<size_t>(colorAccessor)].type == TINYGLTF_TYPE_VEC3
                              ? TINYGLTF_TYPE_VEC3
                              : TINYGLTF_TYPE_VEC4;
    const std::vector<float> colors =
        colorAccessor >= 0 ? read("COLOR_0", colorType, {kFloat, kUbyte, kUshort}, count) : std::vector<float>();

    MeshData mesh;
    mesh.vertices.resize(count);
    for (size_t i = 0; i < count; ++i) {
      Vertex& v = mesh.vertices[i];
      v.position = glm::vec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
      v.normal = hasNormals ? glm::vec3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]) : glm::vec3(0.0f);
      v.uv = uvs.empty() ? glm::vec2(0.0f) : glm::vec2(uvs[2 * i], uvs[2 * i + 1]);
      v.tangent = hasTangents ? glm::vec4(tangents[4 * i], tangents[4 * i + 1], tangents[4 * i + 2],
                                          tangents[4 * i + 3] < 0.0f ? -1.0f : 1.0f)
                              : glm::vec4(0.0f);
    }
    if (!uv1.empty()) {
      mesh.uv1.resize(count);
      for (size_t i = 0; i < count; ++i) mesh.uv1[i] = glm::vec2(uv1[2 * i], uv1[2 * i + 1]);
    }
    if (!colors.empty()) {
      // Colours are factors in [0, 1]; a float outside is clamped, so that no surface reflects more than it
      // receives or less than nothing.
      bool clamped = false;
      mesh.colors.resize(count);
      for (size_t i = 0; i < count; ++i) {
        glm::vec4 c(1.0f);
        for (int k = 0; k < colorType; ++k) c[k] = colors[static_cast<size_t>(colorType) * i + static_cast<size_t>(k)];
        mesh.colors[i] = glm::clamp(c, 0.0f, 1.0f);
        clamped = clamped || mesh.colors[i] != c;
      }
      if (clamped) file_.warn(field + ".attributes.COLOR_0: values outside [0, 1] clamped");
    }
    std::vector<uint32_t> indices;
    if (draco) {
      indices = draco->indices;
    } else if (prim.indices >= 0) {
      indices = readIndexAccessor(file_, prim.indices, count, field + ".indices");
    } else {
      indices.resize(count);
      std::iota(indices.begin(), indices.end(), 0u);
    }
    mesh.indices = triangleList(file_, prim.mode, std::move(indices),
                                field + (prim.indices >= 0 ? ".indices" : ".attributes.POSITION"));
    if (!pose_ && !mesh.indices.empty() && !coversArea(mesh)) {
      const size_t triangles = mesh.indices.size() / 3;
      file_.warn(field + (triangles == 1 ? ": its triangle has" : ": its " + std::to_string(triangles) +
                                                                      " triangles all have") +
                 " zero area (repeated indices, or positions in one point or line): it draws nothing");
    }
    if (!hasNormals) {
      makeFlatNormals(mesh);
    } else {
      repairNormals(mesh);
    }
    if (!hasTangents) generateTangents(mesh);
    return mesh;
  }

  void addLight(const tinygltf::Value& extension, const glm::mat4& world, const std::string& field) {
    const tinygltf::Value& ref = extension.Get("light");
    const auto& lights = file_.model.lights;
    if (!ref.IsNumber() || ref.GetNumberAsInt() < 0 || static_cast<size_t>(ref.GetNumberAsInt()) >= lights.size()) {
      file_.fail(field + ".light: not the index of one of the file's " + std::to_string(lights.size()) + " lights");
    }
    const int index = ref.GetNumberAsInt();
    const tinygltf::Light& l = lights[static_cast<size_t>(index)];
    const std::string name = "extensions.KHR_lights_punctual." + gltfElement("lights", index);
    if (l.type != "point" && l.type != "spot" && l.type != "directional") {
      file_.fail(name + ".type: expected \"point\", \"spot\" or \"directional\" (got \"" + l.type + "\")");
    }
    glm::vec3 color(1.0f);
    if (!l.color.empty()) {
      const std::vector<double> c = checkedArray(file_, l.color, 3, name + ".color");
      color = glm::vec3(c[0], c[1], c[2]);
      if (glm::any(glm::lessThan(color, glm::vec3(0.0f)))) file_.fail(name + ".color: must be >= 0");
    }
    if (!std::isfinite(l.intensity) || l.intensity < 0.0) file_.fail(name + ".intensity: must be a finite number >= 0");
    if (l.type == "directional") {
      // Under a node scaled to nothing: no light, shining down.
      addDirectionalLight(hiddenNode_ ? glm::mat4(1.0f) : world, color, hiddenNode_ ? 0.0 : l.intensity, name);
      return;
    }
    PointLight light;
    light.castsShadows = true;  // Blender's lights cast shadows unless told not to; glTF has no word for it
    light.position = glm::vec3(world[3]);
    light.color = color;
    if (!std::isfinite(l.range) || l.range < 0.0) file_.fail(name + ".range: must be a positive finite number");
    // Exporters write an "infinite" range as FLT_MAX (babylon.js for 3ds Max); glTF's word for it is no range.
    const bool bounded = l.range > 0.0 && l.range <= kMaxCoordinate;  // tinygltf reads an absent range as 0
    if (l.range > kMaxCoordinate) {
      file_.warn(name + ".range: " + number(l.range) + " is beyond the coordinate limit " + number(kMaxCoordinate) +
                 ": read as no range (the light ends where it gives " + number(kGltfLightCutoffIlluminance) +
                 " lux)");
    }
    const float intensity = static_cast<float>(l.intensity);  // candela
    // A point source of intensity I emits P = 4 pi I lumens.
    light.luminousPower = 4.0f * kPi * intensity;
    const float brightest = std::max({light.color.x, light.color.y, light.color.z});
    light.radius =
        bounded ? static_cast<float>(l.range) : std::sqrt(intensity * brightest / kGltfLightCutoffIlluminance);
    // Values finite as written may overflow float once converted or multiplied; name what the file wrote.
    if (!std::isfinite(light.luminousPower)) file_.fail(name + ".intensity: too large (got " + number(l.intensity) + ")");
    if (!std::isfinite(brightest)) file_.fail(name + ".color: too large");
    if (!(light.radius <= kMaxCoordinate)) {
      file_.fail(name + (bounded ? ".range" : ".intensity") + ": gives a light radius beyond the coordinate limit " +
                 number(kMaxCoordinate));
    }
    if (l.type == "spot") light.spot = spotCone(l.spot, hiddenNode_ ? glm::mat4(1.0f) : world, name);
    if (hiddenNode_) {  // under a node scaled to nothing: reaches nothing
      light.luminousPower = 0.0f;
      light.radius = 0.0f;
      light.castsShadows = false;
    }
    if (pose_) {
      scene_.lights.at(nextLight_++) = light;
    } else {
      scene_.lights.push_back(light);
    }
  }

  // KHR_lights_punctual: a spot light shines along its node's local -Z; 0 <= inner < outer <= pi/2.
  SpotCone spotCone(const tinygltf::SpotLight& spot, const glm::mat4& world, const std::string& name) {
    const glm::vec3 direction = glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f);
    const float length = glm::length(direction);
    if (!(length > 0.0f) || !std::isfinite(length)) file_.fail(name + ": its node's transform leaves no direction");
    if (!(spot.outerConeAngle > 0.0 && spot.outerConeAngle <= kPi / 2.0 + 1e-6)) {
      file_.fail(name + ".spot.outerConeAngle: must be in (0, pi/2] (got " + number(spot.outerConeAngle) + ")");
    }
    if (!(spot.innerConeAngle >= 0.0 && spot.innerConeAngle < spot.outerConeAngle)) {
      file_.fail(name + ".spot.innerConeAngle: must be in [0, outerConeAngle) (got " + number(spot.innerConeAngle) +
                 ")");
    }
    SpotCone cone;
    cone.direction = direction / length;
    cone.outerAngle = std::min(static_cast<float>(spot.outerConeAngle), glm::half_pi<float>());
    cone.innerAngle = std::min(static_cast<float>(spot.innerConeAngle), cone.outerAngle);
    return cone;
  }

  // KHR_lights_punctual: a directional light shines along its node's local -Z, with illuminance in lux.
  void addDirectionalLight(const glm::mat4& world, const glm::vec3& color, double lux, const std::string& name) {
    const glm::vec3 direction = glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f);
    const float length = glm::length(direction);
    if (!(length > 0.0f) || !std::isfinite(length)) file_.fail(name + ": its node's transform leaves no direction");
    const float illuminance = static_cast<float>(lux);
    if (!std::isfinite(illuminance)) file_.fail(name + ".intensity: too large (got " + number(lux) + ")");
    const DirectionalLight light{direction / length, color, illuminance};
    if (pose_) {
      scene_.directionalLights.at(nextDirectional_++) = light;
    } else {
      scene_.directionalLights.push_back(light);
    }
  }

  const GltfFile& file_;
  Scene& scene_;
  LoadedGltf& loaded_;
  GltfMaterials materials_;
  std::vector<std::pair<Camera, bool>> cameras_;  // and whether the file left its far plane out
  GltfSelection selection_;
  glm::mat4 placement_{1.0f};                    // the load's transform, before the scene's roots
  std::vector<AnimatedNode> animated_;           // by node: what the chosen animation sets, nothing at rest
  std::vector<std::optional<glm::mat4>> worlds_;  // by node: its world transform, for the nodes of the scene
  std::vector<int> parents_;                     // by node: its parent, -1 for a root
  std::vector<bool> hidden_;                     // by node: scaled to nothing by the animation, or under one
  Bounds bounds_;
  bool empty_ = true;
  bool hiddenNode_ = false;  // the node placing what is added now is scaled to nothing (a playable load keeps it)
  // Posing a playable load (pose): where its objects and lights are rewritten, and the meshes rewritten.
  const GltfPlayback* pose_ = nullptr;
  std::vector<int>* changed_ = nullptr;
  size_t nextObject_ = 0, nextLight_ = 0, nextDirectional_ = 0;
};

// Two names of one file (relative, absolute, through a link) share one record.
std::string fileKey(const std::string& path) {
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::canonical(path, error);
  return error ? path : canonical.string();
}

}  // namespace

Bounds appendGltf(Scene& scene, const std::string& path, const glm::mat4& transform, const UriPolicy& policy,
                  const GltfSelection& selection) {
  // Read and checked again on every load: the policy may differ, and the checks blame this load's fields.
  GltfFile file = readGltfFile(path, policy);
  const std::string key = fileKey(path);
  const auto known = scene.gltfFiles.find(key);
  // Worked on as a copy: a load that fails leaves the record as it was, with the rest of the scene.
  LoadedGltf loaded = known == scene.gltfFiles.end() ? LoadedGltf{} : known->second;
  const size_t meshes = scene.meshes.size(), textures = scene.textures.size(), objects = scene.objects.size(),
               lights = scene.lights.size(), directionalLights = scene.directionalLights.size(),
               cameras = scene.cameras.size();
  try {
    const Bounds bounds = Loader(file, scene, loaded, selection).load(transform);
    if (selection.playable && selection.animated()) {
      auto playback = std::make_shared<GltfPlayback>();
      const int animation = findAnimation(file, selection);
      playback->animationName = file.model.animations[static_cast<size_t>(animation)].name;
      if (playback->animationName.empty()) playback->animationName = gltfElement("animations", animation);
      playback->duration = animationDuration(file, animation);
      playback->key = key;
      playback->transform = transform;
      playback->selection = selection;
      playback->firstObject = objects;
      playback->firstLight = lights;
      playback->firstDirectionalLight = directionalLights;
      playback->file = std::make_shared<const GltfFile>(std::move(file));
      scene.gltfPlayback.push_back(std::move(playback));
    }
    scene.gltfFiles[key] = std::move(loaded);
    return bounds;
  } catch (...) {
    // A file found malformed half-way leaves the scene as it was.
    scene.meshes.resize(meshes);
    scene.textures.resize(textures);
    scene.objects.resize(objects);
    scene.lights.resize(lights);
    scene.directionalLights.resize(directionalLights);
    scene.cameras.resize(cameras);
    throw;
  }
}

std::vector<int> posePlayback(Scene& scene, double time) {
  std::vector<int> changed;
  for (const std::shared_ptr<const GltfPlayback>& playback : scene.gltfPlayback) {
    GltfSelection selection = playback->selection;
    selection.time = time;
    Loader(*playback->file, scene, scene.gltfFiles.at(playback->key), selection).pose(*playback, changed);
  }
  return changed;
}

}  // namespace pbr
