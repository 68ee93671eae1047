#include "core/scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "core/scene/exposure.hpp"

namespace pbr {

SpotFalloff spotFalloff(const SpotCone& cone) {
  const float cosOuter = std::cos(cone.outerAngle);
  const float scale = 1.0f / std::max(1e-3f, std::cos(cone.innerAngle) - cosOuter);
  return {scale, -cosOuter * scale};
}

ShadowMode parseShadowMode(const std::string& name) {
  if (name == "none") return ShadowMode::None;
  if (name == "on") return ShadowMode::On;
  if (name == "auto") return ShadowMode::Auto;
  throw std::invalid_argument("unknown shadow mode '" + name + "' (expected none, on or auto)");
}

const char* toString(ShadowMode mode) {
  switch (mode) {
    case ShadowMode::None: return "none";
    case ShadowMode::On: return "on";
    case ShadowMode::Auto: return "auto";
  }
  return "?";
}

float Scene::displayExposure() const {
  return ev100 ? static_cast<float>(exposure * exposureFromEv100(*ev100)) : exposure;
}

SceneObject& Scene::addShape(Shape shape, const glm::mat4& transform, const Material& material) {
  int mesh = -1;
  for (const SceneObject& o : objects) {
    if (o.shape == shape) mesh = o.mesh;
  }
  if (mesh < 0) {
    meshes.push_back(shape == Shape::Plane ? makePlaneMesh() : shape == Shape::Sphere ? makeSphereMesh() : makeBoxMesh());
    mesh = static_cast<int>(meshes.size()) - 1;
  }
  objects.push_back({shape, mesh, transform, material});
  return objects.back();
}

namespace {

class Checker {
 public:
  explicit Checker(const std::string& source) : source_(source) {}

  void finite(const std::string& field, float v) const {
    if (!std::isfinite(v)) fail(field, "must be a finite number", v);
  }
  void finite(const std::string& field, const glm::vec3& v) const {
    for (int i = 0; i < 3; ++i) finite(field + "[" + std::to_string(i) + "]", v[i]);
  }
  void atLeast(const std::string& field, float v, float lo) const {
    finite(field, v);
    if (v < lo) fail(field, "must be >= " + number(lo), v);
  }
  void inRange(const std::string& field, float v, float lo, float hi) const {
    finite(field, v);
    if (v < lo || v > hi) fail(field, "must be in [" + number(lo) + ", " + number(hi) + "]", v);
  }
  void color(const std::string& field, const glm::vec3& v) const {
    for (int i = 0; i < 3; ++i) atLeast(field + "[" + std::to_string(i) + "]", v[i], 0.0f);
  }
  [[noreturn]] void fail(const std::string& field, const std::string& what, float got) const {
    throw SceneError(source_ + ": " + field + ": " + what + " (got " + number(got) + ")");
  }

 private:
  static std::string number(float v) {
    std::ostringstream ss;
    ss << v;
    return ss.str();
  }
  std::string source_;
};

}  // namespace

void validateScene(const Scene& scene, const std::string& source) {
  const Checker c(source);
  const Camera& cam = scene.camera;
  c.finite("camera.position", cam.position);
  c.finite("camera.target", cam.target);
  c.finite("camera.up", cam.up);
  c.inRange("camera.fov_y_deg", cam.fovYDeg, 1.0f, 179.0f);
  if (cam.orthographic) c.inRange("camera.ortho_half_height", cam.orthoHalfHeight, 1e-6f, 1e6f);
  c.atLeast("camera.near", cam.nearPlane, 1e-6f);
  if (!(cam.farPlane > cam.nearPlane)) c.fail("camera.far", "must be greater than camera.near", cam.farPlane);
  c.atLeast("exposure", scene.exposure, 0.0f);
  if (scene.ev100) c.inRange("camera.ev100", *scene.ev100, -kMaxEv100, kMaxEv100);
  c.color("ambient", scene.ambient);
  if (scene.environment) {
    const EnvironmentDesc& e = *scene.environment;
    c.atLeast("environment.intensity", e.intensity, 0.0f);
    c.finite("environment.rotation_deg", e.rotationDeg);
    if (e.file.empty()) {
      c.color("environment.sky.zenith", e.sky.zenith);
      c.color("environment.sky.horizon", e.sky.horizon);
      c.color("environment.sky.ground", e.sky.ground);
      c.finite("environment.sky.sun_direction", e.sky.sunDirection);
      if (glm::length(e.sky.sunDirection) == 0.0f) c.fail("environment.sky.sun_direction", "must not be zero", 0.0f);
      const float r = e.sky.sunAngularRadiusDeg;
      if (!(r > 0.0f && r < 90.0f)) c.fail("environment.sky.sun_angular_radius_deg", "must be in (0, 90)", r);
      c.color("environment.sky.sun_radiance", e.sky.sunRadiance);
    }
  }
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const std::string base = "objects[" + std::to_string(i) + "]";
    const SceneObject& o = scene.objects[i];
    if (o.mesh < 0 || o.mesh >= static_cast<int>(scene.meshes.size())) c.fail(base + ".mesh", "no such mesh", float(o.mesh));
    for (int col = 0; col < 4; ++col) c.finite(base + ".transform", glm::vec3(o.transform[col]));
    c.color(base + ".material.base_color", o.material.baseColor);
    c.inRange(base + ".material.roughness", o.material.roughness, 0.0f, 1.0f);
    c.inRange(base + ".material.metalness", o.material.metalness, 0.0f, 1.0f);
    const Material& m = o.material;
    c.color(base + ".material.emissive", m.emissive);
    c.inRange(base + ".material.alpha", m.alpha, 0.0f, 1.0f);
    c.finite(base + ".material.alpha_cutoff", m.alphaCutoff);
    c.finite(base + ".material.normal_scale", m.normalScale);
    c.inRange(base + ".material.occlusion_strength", m.occlusionStrength, 0.0f, 1.0f);
    const std::pair<const char*, int> maps[] = {{"base_color_texture", m.baseColorTexture},
                                                {"metallic_roughness_texture", m.metallicRoughnessTexture},
                                                {"normal_texture", m.normalTexture},
                                                {"occlusion_texture", m.occlusionTexture},
                                                {"emissive_texture", m.emissiveTexture}};
    for (const auto& [name, index] : maps) {
      if (index < -1 || index >= static_cast<int>(scene.textures.size())) {
        c.fail(base + ".material." + name, "no such texture", float(index));
      }
    }
  }
  for (size_t i = 0; i < scene.textures.size(); ++i) {
    const TextureData& t = scene.textures[i];
    const std::string base = "textures[" + std::to_string(i) + "] (" + t.name + ")";
    c.atLeast(base + ".width", float(t.width), 1.0f);
    c.atLeast(base + ".height", float(t.height), 1.0f);
    if (t.rgba.size() != static_cast<size_t>(t.width) * static_cast<size_t>(t.height) * 4) {
      c.fail(base + ".rgba", "must hold width x height x 4 bytes", float(t.rgba.size()));
    }
  }
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const std::string base = "lights[" + std::to_string(i) + "]";
    const PointLight& l = scene.lights[i];
    c.finite(base + ".position", l.position);
    c.atLeast(base + ".radius", l.radius, 0.0f);
    c.color(base + ".color", l.color);
    c.atLeast(base + ".luminous_power", l.luminousPower, 0.0f);
    if (!l.spot) continue;
    c.finite(base + ".direction", l.spot->direction);
    if (!(std::abs(glm::length(l.spot->direction) - 1.0f) <= 1e-3f)) {
      c.fail(base + ".direction", "must be a unit vector", glm::length(l.spot->direction));
    }
    c.inRange(base + ".outer_angle", l.spot->outerAngle, 0.0f, glm::half_pi<float>());
    c.inRange(base + ".inner_angle", l.spot->innerAngle, 0.0f, l.spot->outerAngle);
  }
  if (scene.directionalLights.size() > kMaxDirectionalLights) {
    c.fail("directional lights", "at most " + std::to_string(kMaxDirectionalLights) + " are shaded",
           float(scene.directionalLights.size()));
  }
  for (size_t i = 0; i < scene.directionalLights.size(); ++i) {
    const std::string base = "directional_lights[" + std::to_string(i) + "]";
    const DirectionalLight& l = scene.directionalLights[i];
    c.finite(base + ".direction", l.direction);
    if (std::abs(glm::length(l.direction) - 1.0f) > 1e-3f) {
      c.fail(base + ".direction", "must be a unit vector", glm::length(l.direction));
    }
    c.color(base + ".color", l.color);
    c.atLeast(base + ".illuminance", l.illuminance, 0.0f);
  }
}

bool hasBlendMaterial(const Scene& scene) {
  return std::any_of(scene.objects.begin(), scene.objects.end(),
                     [](const SceneObject& o) { return o.material.alphaMode == AlphaMode::Blend; });
}

bool hasTransmissiveMaterial(const Scene& scene) {
  return std::any_of(scene.objects.begin(), scene.objects.end(),
                     [](const SceneObject& o) { return isTransmissive(o.material); });
}

std::array<const MaterialMap*, kExtensionMapCount> extensionMaps(const Material& m) {
  return {&m.clearcoatMap,     &m.clearcoatRoughnessMap, &m.clearcoatNormalMap, &m.sheenColorMap, &m.sheenRoughnessMap,
          &m.specularMap,      &m.specularColorMap,      &m.transmissionMap,    &m.thicknessMap};
}

bool readsTexCoord1(const Material& m) {
  const std::array<const MaterialMap*, kExtensionMapCount> maps = extensionMaps(m);
  return (m.baseColorTexture >= 0 && m.baseColorTexCoord == 1) ||
         (m.metallicRoughnessTexture >= 0 && m.metallicRoughnessTexCoord == 1) ||
         (m.normalTexture >= 0 && m.normalTexCoord == 1) || (m.occlusionTexture >= 0 && m.occlusionTexCoord == 1) ||
         (m.emissiveTexture >= 0 && m.emissiveTexCoord == 1) ||
         std::any_of(maps.begin(), maps.end(),
                     [](const MaterialMap* map) { return map->texture >= 0 && map->texCoord == 1; });
}

glm::vec4 dielectricSpecular(const Material& m) {
  // KHR_materials_ior: F0 = ((ior - 1) / (ior + 1))^2; KHR_materials_specular: times the colour, clamped to 1,
  // times the strength, which is also F90. In double, as a quotient of squares, so that ior 1.5 gives 0.04.
  const double ior = m.ior;
  const double f0 = (ior - 1.0) * (ior - 1.0) / ((ior + 1.0) * (ior + 1.0));
  const glm::dvec3 color = glm::min(f0 * glm::dvec3(m.specularColor), glm::dvec3(1.0)) * double(m.specular);
  return glm::vec4(glm::vec3(color), m.specular);
}

bool hasClearcoat(const Material& m) { return m.clearcoat > 0.0f; }

bool hasSheen(const Material& m) { return m.sheenColor != glm::vec3(0.0f); }

bool isTransmissive(const Material& m) { return m.transmission > 0.0f && !m.unlit; }

bool isForwardShaded(const Material& m) { return m.alphaMode == AlphaMode::Blend || isTransmissive(m); }

bool passesShadowRays(const Material& m) { return isTransmissive(m) && m.transmission > kTransmissionShadowCutoff; }

bool hasDielectricSpecular(const Material& m) { return dielectricSpecular(m) != glm::vec4(glm::vec3(0.04f), 1.0f); }

bool hasUnlitSurface(const Scene& scene) {
  return std::any_of(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) {
    return o.material.unlit && o.material.alphaMode != AlphaMode::Blend;
  });
}

}  // namespace pbr
