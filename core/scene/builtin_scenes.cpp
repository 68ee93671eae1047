#include "core/scene/builtin_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include <glm/common.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/scene/gltf_loader.hpp"
#include "core/scene/random.hpp"
#include "core/scene/scene_json.hpp"

namespace pbr {

namespace {

glm::vec3 hueToRgb(float h) {
  const float r = std::clamp(std::abs(h * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
  const float g = std::clamp(2.0f - std::abs(h * 6.0f - 2.0f), 0.0f, 1.0f);
  const float b = std::clamp(2.0f - std::abs(h * 6.0f - 4.0f), 0.0f, 1.0f);
  return {r, g, b};
}

// `--lights N` for the scenes whose files list their lights; each keeps the meaning N had for it before the
// files were its definition, so that light-count sweeps and experiments give the same frames.

// The grid's four corner lights give way to N random ones in front of it, whose total power does not grow with N.
void randomGridLights(Scene& s, int count) {
  RandomLightSpec spec;
  spec.count = count;
  spec.boundsMin = {-6.0f, -6.0f, 1.0f};
  spec.boundsMax = {6.0f, 6.0f, 6.0f};
  spec.radiusMin = 3.0f;
  spec.radiusMax = 10.0f;
  spec.powerMin = 500.0f / count;
  spec.powerMax = 2000.0f / count;
  s.lights = makeRandomLights(spec);
}

// N copies of the file's light: the co-located lights of the saturation experiment.
void colocatedLights(Scene& s, int count) {
  if (s.lights.empty()) throw SceneError(s.name + ": the scene file has no light to repeat");
  s.lights.assign(static_cast<size_t>(count), s.lights.front());
}

void singleLight(Scene& s, int count) {
  if (count != 1) throw SceneError(s.name + ": the scene has exactly one light");
}

// The world bounds of the scene's glTF models, as appendGltf measured them while loading.
Bounds modelBounds(const Scene& s) {
  Bounds b{glm::vec3(std::numeric_limits<float>::infinity()), glm::vec3(-std::numeric_limits<float>::infinity())};
  for (const SceneObject& o : s.objects) {
    if (o.shape != Shape::Mesh) continue;
    for (const Vertex& v : s.meshes[static_cast<size_t>(o.mesh)].vertices) {
      const glm::vec3 w(o.transform * glm::vec4(v.position, 1.0f));
      b.min = glm::min(b.min, w);
      b.max = glm::max(b.max, w);
    }
  }
  return b;
}

// N lights of hues around the colour wheel on a ring about the model, in three tiers from its bottom to above its
// top; their total power stays the same whatever N.
void lightRing(Scene& s, int count) {
  const Bounds b = modelBounds(s);
  const glm::vec3 center = 0.5f * (b.min + b.max);
  const float size = std::max({b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z});
  s.lights.clear();
  for (int i = 0; i < count; ++i) {
    const float angle = 2.0f * 3.14159265f * (i + 0.5f) / static_cast<float>(count);
    const float height = 0.15f + 0.35f * static_cast<float>(i % 3);
    PointLight l;
    l.position = center + glm::vec3(std::cos(angle) * 1.3f, height - 0.2f, std::sin(angle) * 1.3f) * size;
    l.radius = 3.0f * size;
    l.color = hueToRgb((i + 0.5f) / static_cast<float>(count));
    l.luminousPower = 1500.0f / static_cast<float>(count);
    s.lights.push_back(l);
  }
}

// `--view-angle DEG`: the camera circles the floor's centre at 6 units, DEG from the normal, and the light follows
// 1.5 units from it in the mirror direction, so that the highlight stays at the centre of the frame. The file
// holds the scene at 40 degrees.
void viewFloorAt(Scene& s, float angle) {
  if (!(angle >= 0.0f && angle <= 89.0f)) {
    throw SceneError(s.name + ": view angle must be in [0, 89] degrees (got " + std::to_string(angle) + ")");
  }
  if (s.lights.size() != 1) throw SceneError(s.name + ": the scene file must have exactly one light");
  const float theta = glm::radians(angle);
  s.camera.position = glm::vec3(0.0f, std::cos(theta), std::sin(theta)) * 6.0f;
  // Looking straight down, "up" must not be parallel to the view direction.
  s.camera.up = angle < 1.0f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  s.lights.front().position = glm::vec3(0.0f, std::cos(theta), -std::sin(theta)) * 1.5f;
}

struct Builtin {
  const char* name;
  // Applies --lights to the loaded scene; null where the count replaces the file's random_lights.count.
  void (*setLightCount)(Scene&, int);
  // Applies --view-angle; null where the scene has none (the parameter is ignored).
  void (*setViewAngle)(Scene&, float);
};

const Builtin kBuiltins[] = {{"default", nullptr, nullptr},
                             {"sphere-grid", randomGridLights, nullptr},
                             {"light-wall", colocatedLights, nullptr},
                             {"fresnel-floor", singleLight, viewFloorAt},
                             {"stress", nullptr, nullptr},
                             {"helmet", lightRing, nullptr},
                             {"helmet-grid", nullptr, nullptr},
                             {"many-lights", nullptr, nullptr},
                             {"shadow-trio", nullptr, nullptr},
                             {"transparency", nullptr, nullptr},
                             {"material-specular", nullptr, nullptr},
                             {"material-clearcoat", nullptr, nullptr},
                             {"material-sheen", nullptr, nullptr},
                             {"material-transmission", nullptr, nullptr},
                             {"materials", nullptr, nullptr}};

const Builtin* findBuiltin(const std::string& name) {
  const auto it =
      std::find_if(std::begin(kBuiltins), std::end(kBuiltins), [&](const Builtin& b) { return name == b.name; });
  return it == std::end(kBuiltins) ? nullptr : it;
}

std::string builtinScenePath(const std::string& name) {
  const std::string path = (std::filesystem::path(builtinSceneDir()) / (name + ".json")).string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw SceneError(path + ": built-in scene file not found (PBR_SCENE_DIR names the folder of the built-in scenes)");
  }
  return path;
}

}  // namespace

std::vector<PointLight> makeRandomLights(const RandomLightSpec& spec) {
  Pcg32 rng(spec.seed);
  std::vector<PointLight> lights;
  lights.reserve(static_cast<size_t>(std::max(spec.count, 0)));
  for (int i = 0; i < spec.count; ++i) {
    PointLight l;
    l.position = {rng.uniform(spec.boundsMin.x, spec.boundsMax.x), rng.uniform(spec.boundsMin.y, spec.boundsMax.y),
                  rng.uniform(spec.boundsMin.z, spec.boundsMax.z)};
    l.radius = rng.uniform(spec.radiusMin, spec.radiusMax);
    l.color = hueToRgb(rng.uniform());
    l.luminousPower = rng.uniform(spec.powerMin, spec.powerMax);
    lights.push_back(l);
  }
  if (spec.spotShare <= 0.0f) return lights;
  // A stream of its own, so that the share leaves the lights' positions, radii, colours and powers as they were.
  Pcg32 spots(spec.seed, 0x5907u);
  for (PointLight& l : lights) {
    if (!(spots.uniform() < spec.spotShare)) continue;
    SpotCone cone;
    const float down = spots.uniform(), azimuth = spots.uniform(0.0f, 2.0f * glm::pi<float>());
    const float across = std::sqrt(std::max(0.0f, 1.0f - down * down));
    cone.direction = glm::normalize(glm::vec3(across * std::cos(azimuth), -down, across * std::sin(azimuth)));
    cone.outerAngle = glm::radians(spots.uniform(10.0f, 60.0f));
    cone.innerAngle = cone.outerAngle * spots.uniform(0.0f, 0.9f);
    l.spot = cone;
  }
  return lights;
}

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names;
  for (const Builtin& b : kBuiltins) names.push_back(b.name);
  return names;
}

bool isBuiltinScene(const std::string& name) { return findBuiltin(name) != nullptr; }

std::string builtinSceneDir() {
  const char* env = std::getenv("PBR_SCENE_DIR");
  return env && *env ? env : PBR_SCENE_DIR;
}

Scene makeBuiltinScene(const std::string& name, const SceneParams& params) {
  if (params.lights && *params.lights < 0) throw SceneError(name + ": light count must be >= 0");
  const Builtin* builtin = findBuiltin(name);
  if (!builtin) {
    std::string list;
    for (const Builtin& b : kBuiltins) list += std::string(list.empty() ? "" : ", ") + b.name;
    throw SceneError("unknown scene '" + name + "' (built-in scenes: " + list + ")");
  }
  const int fileLightCount = builtin->setLightCount ? -1 : params.lights.value_or(-1);
  if (params.spotShare && builtin->setLightCount) {
    throw SceneError(name + ": a spot-light share applies to the scenes of random lights (default, stress, "
                            "helmet-grid, many-lights)");
  }
  Scene scene = loadSceneFile(builtinScenePath(name), fileLightCount, params.uris, params.strictKeys,
                              params.defaultEnvironment, params.spotShare, params.gltfSelection);
  if (params.viewAngleDeg && builtin->setViewAngle) builtin->setViewAngle(scene, *params.viewAngleDeg);
  if (params.lights && builtin->setLightCount) builtin->setLightCount(scene, *params.lights);
  return scene;
}

}  // namespace pbr
