#include "core/scene/scene_json.hpp"
#include "core/scene/file_names.hpp"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <tuple>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/vector_relational.hpp>

#include "core/scene/assets.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/exposure.hpp"
#include "core/scene/gltf_loader.hpp"
#include "core/scene/image.hpp"
#include "core/scene/input_file.hpp"
#include "core/scene/json_field.hpp"
#include "core/scene/json_file.hpp"
#include "core/scene/messages.hpp"
#include "core/scene/model_scene.hpp"

namespace pbr {

namespace {

// The file a field names, refused by that field when it is missing or not a regular file.
void requireRegularFile(const JsonField& field, const std::string& path) {
  try {
    pbr::requireRegularFile(path);
  } catch (const std::runtime_error& e) {
    field.fail(e.what());
  }
}


namespace fs = std::filesystem;
using R = NumberRule;

// Positions within the renderer's coordinate limit; a scale between 1e-9 and 1e12 (zero would collapse the normal
// matrix, a negative scale would turn faces inside out).
const R kCoordinate = R::closed(-kMaxCoordinate, kMaxCoordinate);
const R kScale = R::closed(1e-9, kMaxCoordinate);

// The command line's --lights limit: a typo must not allocate gigabytes.
constexpr uint64_t kMaxRandomLights = 1u << 20;

// Paths in a scene file are relative to the file's folder, so that a scene and its assets move together; "asset:"
// names a file of the shared asset folder, which moves on its own (PBR_ASSET_DIR).
constexpr std::string_view kAssetPrefix = "asset:";

std::string resolve(const JsonField& f, const fs::path& folder) {
  const std::string path = f.string();
  if (path.rfind(kAssetPrefix, 0) == 0) {
    try {
      return assetPath(path.substr(kAssetPrefix.size()));
    } catch (const SceneError& e) {
      f.fail(e.what());
    }
  }
  const fs::path p(path);
  return (p.is_absolute() ? p : folder / p).lexically_normal().string();
}

Camera readCamera(const JsonField& f) {
  Camera c;
  c.position = f["position"].vec3(kCoordinate);
  c.target = f["target"].vec3(kCoordinate);
  c.up = f["up"].vec3(R::any(), c.up);
  c.fovYDeg = f["fov_y_deg"].number(R::open(0.0, 180.0), c.fovYDeg);
  if (f["ortho_half_height"].present()) {
    if (f["fov_y_deg"].present()) f.fail("expected fov_y_deg or ortho_half_height, got both");
    c.orthographic = true;
    c.orthoHalfHeight = static_cast<float>(f["ortho_half_height"].number(R::closed(1e-6, 1e6)));
  }
  c.nearPlane = f["near"].number(R::above(0.0), c.nearPlane);
  c.farPlane = f["far"].number(R::above(c.nearPlane, "camera.near"), c.farPlane);
  const glm::vec3 view = c.target - c.position;
  if (glm::length(view) == 0.0f) f["target"].fail("expected a point other than camera.position");
  // lookAt needs an up that is not parallel to the view direction.
  const float upLength = glm::length(c.up);
  if (!(upLength > 0.0f) || glm::length(glm::cross(c.up / upLength, glm::normalize(view))) < 1e-4f) {
    f["up"].fail("expected a direction not parallel to target - position (default [0, 1, 0])");
  }
  return c;
}

// The camera's exposure value at ISO 100, given as such or as the settings that make it; none when neither is given.
std::optional<float> readEv100(const JsonField& f) {
  const JsonField ev100 = f["ev100"], aperture = f["aperture"], shutter = f["shutter_s"], iso = f["iso"];
  const bool settings = aperture.present() || shutter.present() || iso.present();
  if (ev100.present() && settings) f.fail("expected ev100 or aperture, shutter_s and iso, got both");
  if (ev100.present()) return static_cast<float>(ev100.number(R::closed(-kMaxEv100, kMaxEv100)));
  if (!settings) return std::nullopt;
  const double ev = ev100FromCamera(aperture.number(R::above(0.0)), shutter.number(R::above(0.0)),
                                    iso.number(R::above(0.0)));
  if (!(std::abs(ev) <= kMaxEv100)) {
    f.fail("aperture, shutter_s and iso make EV100 " + std::to_string(ev) + ", outside [-64, 64]");
  }
  return static_cast<float>(ev);
}

// M = T * Rz * Ry * Rx * S: scale, then rotate about X, then Y, then Z, then translate.
glm::mat4 readTransform(const JsonField& f) {
  const glm::vec3 translate = f["translate"].vec3(kCoordinate, glm::vec3(0.0f));
  const glm::vec3 rotate = f["rotate_deg"].vec3(R::any(), glm::vec3(0.0f));
  const glm::vec3 scale = f["scale"].vec3OrNumber(kScale, glm::vec3(1.0f));
  glm::mat4 m = glm::translate(glm::mat4(1.0f), translate);
  m = glm::rotate(m, glm::radians(rotate.z), glm::vec3(0.0f, 0.0f, 1.0f));
  m = glm::rotate(m, glm::radians(rotate.y), glm::vec3(0.0f, 1.0f, 0.0f));
  m = glm::rotate(m, glm::radians(rotate.x), glm::vec3(1.0f, 0.0f, 0.0f));
  return glm::scale(m, scale);
}

// Loads an sRGB base colour image once per file, however many materials use it.
int readTexture(const JsonField& f, const fs::path& folder, Scene& scene) {
  const std::string path = resolve(f, folder);
  for (size_t i = 0; i < scene.textures.size(); ++i) {
    if (scene.textures[i].name == path) return static_cast<int>(i);
  }
  ImageRgba8 image;
  try {
    image = readPng(path);
  } catch (const std::runtime_error& e) {
    f.fail(e.what());
  }
  TextureData t;
  t.name = path;
  t.width = image.width;
  t.height = image.height;
  t.rgba = std::move(image.pixels);
  t.srgb = true;
  scene.textures.push_back(std::move(t));
  return static_cast<int>(scene.textures.size()) - 1;
}

Material readMaterial(const JsonField& f, const fs::path& folder, Scene& scene) {
  Material m;
  m.baseColor = f["base_color"].vec3OrNumber(R::closed(0.0, 1.0), m.baseColor);
  m.roughness = f["roughness"].number(R::closed(0.0, 1.0), m.roughness);
  m.metalness = f["metalness"].number(R::closed(0.0, 1.0), m.metalness);
  m.emissive = f["emissive"].vec3OrNumber(R::atLeast(0.0), m.emissive);
  m.doubleSided = f["double_sided"].boolean(m.doubleSided);
  m.unlit = f["unlit"].boolean(m.unlit);
  // KHR_materials_ior and KHR_materials_specular's factors, under the names of the other fields.
  const JsonField ior = f["ior"];
  m.ior = ior.number(R::atLeast(0.0), m.ior);
  if (m.ior > 0.0f && m.ior < 1.0f) ior.fail("must be 0 or at least 1 (an index of refraction)");
  m.specular = f["specular"].number(R::closed(0.0, 1.0), m.specular);
  m.specularColor = f["specular_color"].vec3OrNumber(R::atLeast(0.0), m.specularColor);
  m.clearcoat = f["clearcoat"].number(R::closed(0.0, 1.0), m.clearcoat);
  m.clearcoatRoughness = f["clearcoat_roughness"].number(R::closed(0.0, 1.0), m.clearcoatRoughness);
  m.sheenColor = f["sheen_color"].vec3OrNumber(R::closed(0.0, 1.0), m.sheenColor);
  m.sheenRoughness = f["sheen_roughness"].number(R::closed(0.0, 1.0), m.sheenRoughness);
  // KHR_materials_transmission and KHR_materials_volume's factors.
  m.transmission = f["transmission"].number(R::closed(0.0, 1.0), m.transmission);
  m.thickness = f["thickness"].number(R::atLeast(0.0), m.thickness);
  m.attenuationColor = f["attenuation_color"].vec3OrNumber(R::closed(0.0, 1.0), m.attenuationColor);
  const JsonField distance = f["attenuation_distance"];
  if (distance.present()) m.attenuationDistance = distance.number(R::above(0.0), m.attenuationDistance);
  m.alpha = f["alpha"].number(R::closed(0.0, 1.0), m.alpha);
  const JsonField mode = f["alpha_mode"];
  if (mode.present()) {
    const std::string name = mode.string();
    if (name == "opaque") {
      m.alphaMode = AlphaMode::Opaque;
    } else if (name == "mask") {
      m.alphaMode = AlphaMode::Mask;
    } else if (name == "blend") {
      m.alphaMode = AlphaMode::Blend;
    } else {
      mode.expected("\"opaque\" (the default), \"mask\" or \"blend\"");
    }
  }
  // glTF bounds the cutoff below only; one above 1 cuts the whole surface away.
  m.alphaCutoff = f["alpha_cutoff"].number(R::atLeast(0.0), m.alphaCutoff);
  if (f["base_color_texture"].present()) m.baseColorTexture = readTexture(f["base_color_texture"], folder, scene);
  return m;
}

void readObject(const JsonField& f, const fs::path& folder, const UriPolicy& policy, const GltfSelection& selection,
                Scene& scene) {
  const JsonField shape = f["shape"], gltf = f["gltf"];
  if (shape.present() == gltf.present()) {
    f.fail(shape.present() ? "expected \"shape\" or \"gltf\", got both" : "expected a \"shape\" or a \"gltf\" field");
  }
  const glm::mat4 transform = readTransform(f["transform"]);
  if (gltf.present()) {
    if (f["material"].present()) f["material"].fail("a glTF object takes its materials from its file");
    const std::string path = resolve(gltf, folder);
    requireRegularFile(gltf, path);
    try {
      appendGltf(scene, path, transform, policy, selection);
    } catch (const SceneError& e) {
      gltf.fail(e.what());
    }
    return;
  }
  const std::string name = shape.string();
  if (name != "plane" && name != "box" && name != "sphere") shape.expected("\"plane\", \"box\" or \"sphere\"");
  const Shape s = name == "plane" ? Shape::Plane : name == "box" ? Shape::Box : Shape::Sphere;
  scene.addShape(s, transform, readMaterial(f["material"], folder, scene));
}

// A light's "shadows": its own say, else the scene's, else the light type's default.
bool readCastsShadows(const JsonField& f, std::optional<bool> sceneDefault, bool typeDefault) {
  return f["shadows"].boolean(sceneDefault.value_or(typeDefault));
}

DirectionalLight readDirectionalLight(const JsonField& f, std::optional<bool> sceneShadows) {
  DirectionalLight l;
  l.castsShadows = readCastsShadows(f, sceneShadows, true);
  const glm::vec3 direction = f["direction"].vec3(R::any());
  if (!(glm::length(direction) > 0.0f)) f["direction"].fail("expected a non-zero direction (the way the light travels)");
  l.direction = glm::normalize(direction);
  l.color = f["color"].vec3OrNumber(R::atLeast(0.0), l.color);
  l.illuminance = f["illuminance_lux"].number(R::closed(0.0, kMaxCoordinate));
  return l;
}

PointLight readPointLight(const JsonField& f, std::optional<bool> sceneShadows) {
  PointLight l;
  l.castsShadows = readCastsShadows(f, sceneShadows, false);
  l.position = f["position"].vec3(kCoordinate);
  l.color = f["color"].vec3OrNumber(R::atLeast(0.0), l.color);
  l.radius = f["radius"].number(R::closed(0.0, kMaxCoordinate));
  const JsonField power = f["luminous_power"], intensity = f["intensity_cd"];
  if (power.present() == intensity.present()) {
    f.fail(power.present() ? "expected luminous_power or intensity_cd, got both"
                           : "expected luminous_power (lm) or intensity_cd (cd), got neither");
  }
  // An isotropic point light of intensity I emits P = 4 pi I.
  l.luminousPower = power.present() ? power.number(R::atLeast(0.0))
                                    : 4.0f * glm::pi<float>() * intensity.number(R::atLeast(0.0));
  return l;
}

// A spot light: a point light's fields and its cone, angles in degrees from the axis as in glTF (0 and 45 by
// default).
PointLight readSpotLight(const JsonField& f, std::optional<bool> sceneShadows) {
  PointLight l = readPointLight(f, sceneShadows);
  l.castsShadows = readCastsShadows(f, sceneShadows, true);
  SpotCone cone;
  const glm::vec3 direction = f["direction"].vec3(R::any());
  if (!(glm::length(direction) > 0.0f)) f["direction"].fail("expected a non-zero direction (the way the light shines)");
  cone.direction = glm::normalize(direction);
  const float outerDeg = f["outer_angle_deg"].number(R::closed(0.0, 90.0), glm::degrees(cone.outerAngle));
  const float innerDeg = f["inner_angle_deg"].number(R::closed(0.0, outerDeg), 0.0f);
  cone.outerAngle = glm::radians(outerDeg);
  cone.innerAngle = std::min(glm::radians(innerDeg), cone.outerAngle);
  l.spot = cone;
  return l;
}

std::vector<PointLight> readRandomLights(const JsonField& f, int lightCount, std::optional<float> spotShare) {
  RandomLightSpec spec;
  spec.count = static_cast<int>(f["count"].integer(kMaxRandomLights));
  if (lightCount >= 0) spec.count = lightCount;
  spec.seed = f["seed"].integer(UINT64_MAX, spec.seed);
  const JsonField bounds = f["bounds"];
  const std::vector<JsonField> corners = bounds.items();
  const char* boundsShape = "[[min x, y, z], [max x, y, z]] with min <= max";
  if (!bounds.present() || corners.size() != 2) bounds.expected(boundsShape);
  spec.boundsMin = corners[0].vec3(kCoordinate);
  spec.boundsMax = corners[1].vec3(kCoordinate);
  if (glm::any(glm::greaterThan(spec.boundsMin, spec.boundsMax))) bounds.expected(boundsShape);
  std::tie(spec.radiusMin, spec.radiusMax) = f["radius"].interval(R::closed(0.0, kMaxCoordinate));
  std::tie(spec.powerMin, spec.powerMax) = f["luminous_power"].interval(R::atLeast(0.0));
  spec.spotShare = f["spot_share"].number(R::closed(0.0, 1.0), spec.spotShare);
  if (spotShare) spec.spotShare = *spotShare;
  return makeRandomLights(spec);
}

// A procedural sky: an object whose fields are all optional ({} is the default sky of SkyParams).
SkyParams readSky(const JsonField& f) {
  SkyParams sky;
  sky.zenith = f["zenith"].vec3OrNumber(R::atLeast(0.0), sky.zenith);
  sky.horizon = f["horizon"].vec3OrNumber(R::atLeast(0.0), sky.horizon);
  sky.ground = f["ground"].vec3OrNumber(R::atLeast(0.0), sky.ground);
  sky.sunDirection = f["sun_direction"].vec3(R::any(), sky.sunDirection);
  if (glm::length(sky.sunDirection) == 0.0f) f["sun_direction"].fail("expected a non-zero direction");
  sky.sunAngularRadiusDeg = f["sun_angular_radius_deg"].number(R::open(0.0, 90.0), sky.sunAngularRadiusDeg);
  sky.sunRadiance = f["sun_radiance"].vec3OrNumber(R::atLeast(0.0), sky.sunRadiance);
  return sky;
}

// The file is only checked for existence here: it is decoded, with its own one-line errors, when rendered. "none"
// says no environment where leaving the key out would not: in a scene with glTF models.
std::optional<EnvironmentDesc> readEnvironment(const JsonField& f, const fs::path& folder) {
  if (f.isString()) {
    if (f.string() != "none") f.expected(R"("none" or an object with a "file" or a "sky" field)");
    return std::nullopt;
  }
  const JsonField file = f["file"], sky = f["sky"];
  if (file.present() == sky.present()) {
    f.fail(file.present() ? "expected \"file\" or \"sky\", got both" : "expected a \"file\" or a \"sky\" field");
  }
  EnvironmentDesc e;
  if (file.present()) {
    e.file = resolve(file, folder);
    requireRegularFile(file, e.file);
  } else {
    e.sky = readSky(sky);
  }
  e.intensity = f["intensity"].number(R::atLeast(0.0), e.intensity);
  e.rotationDeg = f["rotation_deg"].number(R::any(), e.rotationDeg);
  return e;
}

Scene readJsonScene(const std::string& path, int lightCount, const UriPolicy& policy, bool strictKeys,
                    DefaultEnvironment defaultEnvironment, std::optional<float> spotShare, const GltfSelection& selection) {
  const nlohmann::json document = readJsonFile(path);
  const JsonField root(document, path);
  if (!document.is_object()) root.expected("a JSON object");
  const fs::path folder = fs::path(path).parent_path();

  Scene scene;
  scene.name = fs::path(path).stem().string();
  scene.camera = readCamera(root["camera"]);
  scene.ev100 = readEv100(root["camera"]);
  scene.exposure = root["exposure"].number(R::closed(0.0, kMaxExposure), scene.exposure);
  scene.ambient = root["ambient"].vec3OrNumber(R::atLeast(0.0), scene.ambient);
  const JsonField environment = root["environment"];
  if (environment.present()) scene.environment = readEnvironment(environment, folder);
  for (const JsonField& o : root["objects"].items()) readObject(o, folder, policy, selection, scene);
  // Scenes of shapes alone were written for their own lights and stay without one; glTF models are lit as a model
  // given alone is.
  if (!environment.present() && !scene.gltfFiles.empty() && defaultEnvironment == DefaultEnvironment::Sky) {
    scene.environment = EnvironmentDesc{};
    scene.notes.push_back("no environment in the file, which places glTF models: lit by the procedural sky "
                          "(\"environment\": \"none\" in the file or --environment none turns it off)");
  }
  // "shadows" of the scene: what its lights cast where they do not say; unsaid, spot and directional lights cast
  // and point lights (and random lights) do not.
  std::optional<bool> sceneShadows;
  if (root["shadows"].present()) sceneShadows = root["shadows"].boolean(false);
  for (const JsonField& l : root["lights"].items()) {
    const std::string type = l["type"].present() ? l["type"].string() : "point";
    if (type == "point") {
      scene.lights.push_back(readPointLight(l, sceneShadows));
    } else if (type == "spot") {
      scene.lights.push_back(readSpotLight(l, sceneShadows));
    } else if (type == "directional") {
      scene.directionalLights.push_back(readDirectionalLight(l, sceneShadows));
    } else {
      l["type"].expected("\"point\" (the default), \"spot\" or \"directional\"");
    }
  }
  const JsonField random = root["random_lights"];
  if (random.present()) {
    std::vector<PointLight> lights = readRandomLights(random, lightCount, spotShare);
    for (PointLight& l : lights) l.castsShadows = sceneShadows.value_or(false);
    scene.lights.insert(scene.lights.end(), lights.begin(), lights.end());
  } else if (lightCount >= 0) {
    random.fail("missing, but a light count was given (it replaces random_lights.count)");
  } else if (spotShare) {
    random.fail("missing, but a spot-light share was given (it replaces random_lights.spot_share)");
  }
  root.reportUnknownKeys(strictKeys);
  // Nothing gives light: the frame is black whatever the objects are. Said, since no key is wrong.
  const bool emits = std::any_of(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) {
    return o.material.emissiveTexture >= 0 || glm::any(glm::greaterThan(o.material.emissive, glm::vec3(0.0f)));
  });
  if (scene.lights.empty() && scene.directionalLights.empty() && !random.present() && !scene.environment &&
      !glm::any(glm::greaterThan(scene.ambient, glm::vec3(0.0f))) && !emits) {
    warnOnce(path + ": no lights, no environment, no ambient light and nothing emissive: the frame is black");
  }
  return scene;
}

}  // namespace

Scene loadSceneFile(const std::string& path, int lightCount, const UriPolicy& policy, bool strictKeys,
                    DefaultEnvironment environment, std::optional<float> spotShare, const GltfSelection& selection) {
  const std::string ext = lowerExtension(path);
  const bool model = ext == ".gltf" || ext == ".glb";
  if (model && (lightCount >= 0 || spotShare)) {
    throw SceneError(path + ": " + (lightCount >= 0 ? "a light count" : "a spot-light share") +
                     " applies only to scene files with random_lights");
  }
  Scene scene = model ? loadModelScene(path, policy, environment, selection)
                      : readJsonScene(path, lightCount, policy, strictKeys, environment, spotShare, selection);
  validateScene(scene, path);
  return scene;
}

}  // namespace pbr
