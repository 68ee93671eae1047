#include "core/builtin_scenes.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/random.hpp"

namespace pbr {

namespace {

glm::vec3 hueToRgb(float h) {
  const float r = std::clamp(std::abs(h * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
  const float g = std::clamp(2.0f - std::abs(h * 6.0f - 2.0f), 0.0f, 1.0f);
  const float b = std::clamp(2.0f - std::abs(h * 6.0f - 4.0f), 0.0f, 1.0f);
  return {r, g, b};
}

// A floor with a 7x7 grid of spheres: metalness rises along +x, roughness along +z.
Scene makeDefaultScene(int lightCount) {
  Scene s;
  s.name = "default";
  s.camera.position = {0.0f, 5.5f, 9.0f};
  s.camera.target = {0.0f, 0.0f, 0.3f};
  s.camera.fovYDeg = 45.0f;
  // Near and far hug the scene so that the exponential depth slices fall where the geometry is.
  s.camera.nearPlane = 0.5f;
  s.camera.farPlane = 40.0f;
  s.exposure = 1.6f;
  s.ambient = glm::vec3(0.03f);
  s.addShape(Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(24.0f, 1.0f, 24.0f)),
             Material{glm::vec3(0.45f), 0.75f, 0.0f});
  const int n = 7;
  const float spacing = 1.2f, radius = 0.45f;
  for (int ix = 0; ix < n; ++ix) {
    for (int iz = 0; iz < n; ++iz) {
      const float metal = static_cast<float>(ix) / (n - 1);
      const float rough = static_cast<float>(iz) / (n - 1);
      const glm::vec3 center((ix - (n - 1) * 0.5f) * spacing, radius, (iz - (n - 1) * 0.5f) * spacing);
      const glm::mat4 t = glm::scale(glm::translate(glm::mat4(1.0f), center), glm::vec3(2.0f * radius));
      s.addShape(Shape::Sphere, t, Material{glm::vec3(0.9f, 0.7f, 0.55f), rough, metal});
    }
  }
  RandomLightSpec spec;
  spec.count = lightCount;
  spec.boundsMin = {-5.5f, 0.3f, -5.5f};
  spec.boundsMax = {5.5f, 2.0f, 5.5f};
  spec.radiusMin = 1.0f;
  spec.radiusMax = 3.0f;
  spec.powerMin = 4.0f;
  spec.powerMax = 20.0f;
  s.lights = makeRandomLights(spec);
  return s;
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
  return lights;
}

std::vector<std::string> builtinSceneNames() { return {"default"}; }

Scene makeBuiltinScene(const std::string& name, int lightCount) {
  if (name == "default") return makeDefaultScene(lightCount);
  throw SceneError("unknown scene '" + name + "' (built-in scenes: default)");
}

}  // namespace pbr
