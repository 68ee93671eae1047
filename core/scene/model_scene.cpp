#include "core/scene/model_scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include "core/scene/exposure.hpp"
#include "core/scene/light_meter.hpp"
#include "core/scene/messages.hpp"

namespace pbr {

namespace {

glm::vec3 centreOf(const Bounds& b) { return 0.5f * (b.min + b.max); }

// The bounding sphere of the box; the floor keeps a flat or point-sized model from collapsing the view.
float radiusOf(const Bounds& b) { return std::max(0.5f * glm::length(b.max - b.min), 1e-3f); }

// glTF gives lights in physical units and carries no exposure: the camera is set as an incident-light meter held at
// the model reads. What the loader invented is brought to that level: the ambient light to look as it does at
// exposure 1, the sky two stops below that, a fill that leaves the file's own lights the key. Black lights leave
// nothing to meter.
void meterExposure(Scene& scene, const Bounds& bounds) {
  const double lux = incidentIlluminance(scene, centreOf(bounds), radiusOf(bounds));
  if (!(lux > 0.0)) return;
  const double ev = std::clamp(ev100FromIlluminance(lux), double(-kMaxEv100), double(kMaxEv100));
  scene.ev100 = static_cast<float>(ev);
  scene.ev100Metered = true;
  const float level = static_cast<float>(1.0 / exposureFromEv100(ev));
  scene.ambient *= level;
  if (scene.environment) scene.environment->intensity *= 0.25f * level;
  scene.notes.push_back("the file's lights give " + fixedDecimals(lux, lux < 10.0 ? 3 : 0) +
                        " lux at the model and glTF carries no exposure: EV100 " + fixedDecimals(ev, 2) +
                        " as an incident-light meter reads it, the default " +
                        (scene.environment ? "sky and ambient light" : "ambient light") +
                        " scaled to match (--ev100 sets another, --exposure multiplies)");
}

}  // namespace

Camera frameBounds(const Bounds& bounds, float fovYDeg) {
  const float radius = radiusOf(bounds);
  // 10% farther than the distance at which the sphere touches the top and bottom of the frame.
  const float distance = 1.1f * radius / std::sin(glm::radians(0.5f * fovYDeg));
  Camera c;
  c.target = centreOf(bounds);
  c.position = c.target + glm::normalize(glm::vec3(0.5f, 0.4f, 1.0f)) * distance;
  c.fovYDeg = fovYDeg;
  // Near and far hug the model so that the exponential depth slices fall on it.
  c.nearPlane = 0.5f * (distance - radius);
  c.farPlane = 2.0f * (distance + radius);
  return c;
}

std::vector<PointLight> defaultLightRig(const Bounds& bounds) {
  struct RigLight {
    glm::vec3 offset;    // from the centre, in bounding radii
    float illuminance;   // at the centre, lm per square scene unit
  };
  const RigLight rig[] = {{{1.5f, 2.0f, 2.0f}, 2.5f}, {{-2.0f, 0.5f, 1.5f}, 0.8f}, {{0.0f, 1.5f, -2.5f}, 1.5f}};
  const float radius = radiusOf(bounds);
  std::vector<PointLight> lights;
  for (const RigLight& r : rig) {
    const float d = glm::length(r.offset) * radius;
    // E = I / d^2 with I = P / (4 pi); the influence radius reaches well past the far side of the model.
    lights.push_back({centreOf(bounds) + r.offset * radius, 8.0f * radius, glm::vec3(1.0f),
                      4.0f * glm::pi<float>() * r.illuminance * d * d});
  }
  return lights;
}

Scene loadModelScene(const std::string& path, const UriPolicy& policy, DefaultEnvironment environment,
                     const GltfSelection& selection) {
  Scene scene;
  scene.name = std::filesystem::path(path).stem().string();
  const Bounds bounds = appendGltf(scene, path, glm::mat4(1.0f), policy, selection);
  // A file of points, lines or bare nodes is valid glTF: it renders as the empty frame it is, and says so.
  if (scene.objects.empty()) scene.notes.push_back("the file has no triangles to draw: the frame shows no geometry");
  scene.framedCamera = frameBounds(bounds, 45.0f);
  // The file's own first camera, as its author placed it; auto-framing where it has none.
  scene.camera = scene.cameras.empty() ? *scene.framedCamera : scene.cameras.front();
  scene.ambient = glm::vec3(0.03f);
  const bool fileLights = !scene.lights.empty() || !scene.directionalLights.empty();
  // A file whose scene places no light (whether or not it lists some) would render by its ambient light alone,
  // almost black: it gets the rig, as glTF viewers light such a file.
  if (!fileLights) {
    scene.lights = defaultLightRig(bounds);
    scene.notes.push_back("the file places no lights: lit by a default rig of three point lights");
  }
  // Core glTF has no way to name an environment: the file is always silent about one.
  if (environment == DefaultEnvironment::Sky) {
    scene.environment = EnvironmentDesc{};
    scene.notes.push_back("no environment in the file: lit by the procedural sky (--environment none turns it off)");
  }
  if (fileLights) meterExposure(scene, bounds);
  return scene;
}

}  // namespace pbr
