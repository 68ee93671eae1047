#include "core/builtin_scenes.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/assets.hpp"
#include "core/gltf_loader.hpp"
#include "core/random.hpp"

namespace pbr {

namespace {

glm::vec3 hueToRgb(float h) {
  const float r = std::clamp(std::abs(h * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
  const float g = std::clamp(2.0f - std::abs(h * 6.0f - 2.0f), 0.0f, 1.0f);
  const float b = std::clamp(2.0f - std::abs(h * 6.0f - 4.0f), 0.0f, 1.0f);
  return {r, g, b};
}

glm::mat4 placed(const glm::vec3& at, const glm::vec3& scale) {
  return glm::scale(glm::translate(glm::mat4(1.0f), at), scale);
}

// A floor with a 7x7 grid of spheres: metalness rises along +x, roughness along +z.
Scene makeDefaultScene(const SceneParams& params) {
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
  s.addShape(Shape::Plane, placed(glm::vec3(0.0f), glm::vec3(24.0f, 1.0f, 24.0f)), Material{glm::vec3(0.45f), 0.75f, 0.0f});
  const int n = 7;
  const float spacing = 1.2f, radius = 0.45f;
  for (int ix = 0; ix < n; ++ix) {
    for (int iz = 0; iz < n; ++iz) {
      Material m;
      m.baseColor = glm::vec3(0.9f, 0.7f, 0.55f);
      m.metalness = static_cast<float>(ix) / (n - 1);
      m.roughness = static_cast<float>(iz) / (n - 1);
      const glm::vec3 center((ix - (n - 1) * 0.5f) * spacing, radius, (iz - (n - 1) * 0.5f) * spacing);
      s.addShape(Shape::Sphere, placed(center, glm::vec3(2.0f * radius)), m);
    }
  }
  RandomLightSpec spec;
  spec.count = params.lights.value_or(256);
  spec.boundsMin = {-5.5f, 0.3f, -5.5f};
  spec.boundsMax = {5.5f, 2.0f, 5.5f};
  spec.radiusMin = 1.0f;
  spec.radiusMax = 3.0f;
  spec.powerMin = 4.0f;
  spec.powerMax = 20.0f;
  s.lights = makeRandomLights(spec);
  return s;
}

// The metalness x roughness grid facing the camera: metalness rises left to right, roughness bottom to top.
Scene makeSphereGrid(const SceneParams& params) {
  Scene s;
  s.name = "sphere-grid";
  s.camera.position = {0.0f, 0.0f, 13.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fovYDeg = 45.0f;
  s.camera.nearPlane = 1.0f;
  s.camera.farPlane = 30.0f;
  s.ambient = glm::vec3(0.02f);
  const int n = 7;
  const float spacing = 1.2f;
  for (int ix = 0; ix < n; ++ix) {
    for (int iy = 0; iy < n; ++iy) {
      Material m;
      m.baseColor = glm::vec3(1.0f, 0.71f, 0.29f);
      m.metalness = static_cast<float>(ix) / (n - 1);
      m.roughness = static_cast<float>(iy) / (n - 1);
      const glm::vec3 center((ix - (n - 1) * 0.5f) * spacing, (iy - (n - 1) * 0.5f) * spacing, 0.0f);
      s.addShape(Shape::Sphere, placed(center, glm::vec3(1.0f)), m);
    }
  }
  const int count = params.lights.value_or(4);
  if (!params.lights) {
    const glm::vec3 corners[4] = {{-4, 4, 5}, {4, 4, 5}, {-4, -4, 5}, {4, -4, 5}};
    for (const glm::vec3& p : corners) s.lights.push_back({p, 30.0f, glm::vec3(1.0f), 500.0f});
  } else {
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
  return s;
}

// A wall facing the camera lit by N lights at one point: P = 50 lm, R = 10 for PBR, colour 1 for Blinn-Phong
// (Blinn-Phong reads a light's colour as its LDR intensity), as in the published saturation experiment.
Scene makeLightWall(const SceneParams& params) {
  Scene s;
  s.name = "light-wall";
  s.camera.position = {0.0f, 0.0f, 4.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.fovYDeg = 60.0f;
  s.camera.nearPlane = 0.5f;
  s.camera.farPlane = 20.0f;
  const glm::mat4 wall = glm::rotate(placed(glm::vec3(0.0f), glm::vec3(1.0f)), glm::radians(90.0f), glm::vec3(1, 0, 0));
  s.addShape(Shape::Plane, glm::scale(wall, glm::vec3(12.0f, 1.0f, 12.0f)), Material{glm::vec3(0.8f), 0.5f, 0.0f});
  const int count = params.lights.value_or(1);
  for (int i = 0; i < count; ++i) s.lights.push_back({glm::vec3(0.0f, 0.0f, 1.0f), 10.0f, glm::vec3(1.0f), 50.0f});
  return s;
}

// A checker-textured diffuse floor seen at `view-angle` degrees from its normal, with one light just above it
// at the mirror direction, so that the highlight sits at the centre of the frame.
Scene makeFresnelFloor(const SceneParams& params) {
  const float angle = params.viewAngleDeg.value_or(40.0f);
  if (!(angle >= 0.0f && angle <= 89.0f)) {
    throw SceneError("fresnel-floor: view angle must be in [0, 89] degrees (got " + std::to_string(angle) + ")");
  }
  const float theta = glm::radians(angle);
  Scene s;
  s.name = "fresnel-floor";
  s.camera.position = glm::vec3(0.0f, std::cos(theta), std::sin(theta)) * 6.0f;
  s.camera.target = glm::vec3(0.0f);
  // Looking straight down, "up" must not be parallel to the view direction.
  s.camera.up = angle < 1.0f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  s.camera.fovYDeg = 40.0f;
  s.camera.nearPlane = 0.5f;
  s.camera.farPlane = 60.0f;

  TextureData checker;
  checker.name = "checker";
  checker.width = checker.height = 256;
  checker.srgb = true;
  checker.rgba.resize(256 * 256 * 4);
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      const uint8_t v = ((x / 32 + y / 32) % 2) ? 190 : 150;
      uint8_t* p = &checker.rgba[(static_cast<size_t>(y) * 256 + x) * 4];
      p[0] = v;
      p[1] = v;
      p[2] = static_cast<uint8_t>(v - 20);
      p[3] = 255;
    }
  }
  s.textures.push_back(std::move(checker));
  Material floor{glm::vec3(1.0f), 0.3f, 0.0f};
  floor.baseColorTexture = 0;
  s.addShape(Shape::Plane, placed(glm::vec3(0.0f), glm::vec3(40.0f, 1.0f, 40.0f)), floor);

  const glm::vec3 mirror = glm::vec3(0.0f, std::cos(theta), -std::sin(theta)) * 1.5f;
  s.lights.push_back({mirror, 8.0f, glm::vec3(1.0f), 60.0f});
  if (params.lights && *params.lights != 1) {
    throw SceneError("fresnel-floor: the scene has exactly one light");
  }
  return s;
}

// A large floor with boxes and pillars under many random lights, seen from standing height across a deep view.
Scene makeStress(const SceneParams& params) {
  Scene s;
  s.name = "stress";
  // Between two columns of pillars, slightly above the boxes.
  s.camera.position = {3.5f, 3.0f, 44.0f};
  s.camera.target = {3.5f, 0.5f, 0.0f};
  s.camera.fovYDeg = 60.0f;
  s.camera.nearPlane = 0.1f;
  s.camera.farPlane = 120.0f;
  s.ambient = glm::vec3(0.01f);
  s.exposure = 2.0f;
  s.addShape(Shape::Plane, placed(glm::vec3(0.0f), glm::vec3(90.0f, 1.0f, 90.0f)), Material{glm::vec3(0.5f), 0.6f, 0.0f});
  Pcg32 rng(7);
  for (int ix = -4; ix < 4; ++ix) {
    for (int iz = -4; iz < 4; ++iz) {
      const glm::vec3 base((ix + 0.5f) * 9.0f, 0.0f, (iz + 0.5f) * 9.0f);
      Material m{glm::vec3(rng.uniform(0.3f, 0.9f), rng.uniform(0.3f, 0.9f), rng.uniform(0.3f, 0.9f)),
                 rng.uniform(0.2f, 0.9f), rng.uniform() < 0.3f ? 1.0f : 0.0f};
      const float h = rng.uniform(0.8f, 2.5f);
      s.addShape(Shape::Box, placed(base + glm::vec3(rng.uniform(-2.0f, 2.0f), h * 0.5f, rng.uniform(-2.0f, 2.0f)),
                                    glm::vec3(rng.uniform(1.0f, 3.0f), h, rng.uniform(1.0f, 3.0f))), m);
      s.addShape(Shape::Box, placed(base + glm::vec3(3.5f, 3.0f, 3.5f), glm::vec3(0.5f, 6.0f, 0.5f)),
                 Material{glm::vec3(0.7f), 0.5f, 0.0f});
    }
  }
  RandomLightSpec spec;
  spec.count = params.lights.value_or(1024);
  spec.seed = 11;
  spec.boundsMin = {-40.0f, 0.3f, -40.0f};
  spec.boundsMax = {40.0f, 5.0f, 40.0f};
  spec.radiusMin = 1.5f;
  spec.radiusMax = 4.0f;
  spec.powerMin = 50.0f;
  spec.powerMax = 300.0f;
  s.lights = makeRandomLights(spec);
  return s;
}

// The DamagedHelmet glTF sample (every metal-rough map, an emissive visor) standing on a floor in a ring of
// coloured lights; their total power stays the same whatever their count.
Scene makeHelmet(const SceneParams& params) {
  Scene s;
  s.name = "helmet";
  const Bounds b = appendGltf(s, assetPath("DamagedHelmet/glTF-Binary/DamagedHelmet.glb"));
  const glm::vec3 center = 0.5f * (b.min + b.max);
  const float size = std::max({b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z});
  s.addShape(Shape::Plane, placed(glm::vec3(center.x, b.min.y, center.z), glm::vec3(8.0f * size, 1.0f, 8.0f * size)),
             Material{glm::vec3(0.25f), 0.7f, 0.0f});
  s.camera.position = center + glm::vec3(0.5f, 0.2f, 2.3f) * size;
  s.camera.target = center - glm::vec3(0.0f, 0.05f, 0.0f) * size;
  s.camera.fovYDeg = 40.0f;
  s.camera.nearPlane = 0.05f * size;
  s.camera.farPlane = 10.0f * size;
  s.exposure = 1.2f;
  s.ambient = glm::vec3(0.15f);
  const int count = params.lights.value_or(16);
  for (int i = 0; i < count; ++i) {
    const float angle = 2.0f * 3.14159265f * (i + 0.5f) / static_cast<float>(count);
    const float height = 0.15f + 0.35f * static_cast<float>(i % 3);  // three tiers, bottom to above the top
    PointLight l;
    l.position = center + glm::vec3(std::cos(angle) * 1.3f, height - 0.2f, std::sin(angle) * 1.3f) * size;
    l.radius = 3.0f * size;
    l.color = hueToRgb((i + 0.5f) / static_cast<float>(count));
    l.luminousPower = 1500.0f / static_cast<float>(count);
    s.lights.push_back(l);
  }
  return s;
}

struct Builtin {
  const char* name;
  Scene (*make)(const SceneParams&);
};

const Builtin kBuiltins[] = {{"default", makeDefaultScene},   {"sphere-grid", makeSphereGrid},
                             {"light-wall", makeLightWall},    {"fresnel-floor", makeFresnelFloor},
                             {"stress", makeStress},         {"helmet", makeHelmet}};

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

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names;
  for (const Builtin& b : kBuiltins) names.push_back(b.name);
  return names;
}

bool isBuiltinScene(const std::string& name) {
  return std::any_of(std::begin(kBuiltins), std::end(kBuiltins), [&](const Builtin& b) { return name == b.name; });
}

Scene makeBuiltinScene(const std::string& name, const SceneParams& params) {
  if (params.lights && *params.lights < 0) throw SceneError(name + ": light count must be >= 0");
  for (const Builtin& b : kBuiltins) {
    if (name == b.name) return b.make(params);
  }
  std::string list;
  for (const Builtin& b : kBuiltins) list += std::string(list.empty() ? "" : ", ") + b.name;
  throw SceneError("unknown scene '" + name + "' (built-in scenes: " + list + ")");
}

}  // namespace pbr
