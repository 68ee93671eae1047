#include "app/viewer/scene_snapshot.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include "core/io/output_file.hpp"
#include "core/scene/exposure.hpp"
#include "core/scene/json_file.hpp"
#include "core/scene/scene_json.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace pbr {

namespace {

// The shortest decimal that reads back as the same float, so that the file stays legible (0.1, not
// 0.10000000149011612) and a re-read camera is the viewer's.
json number(float value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  *end = '\0';
  return std::strtod(text, nullptr);
}

json vec3(const glm::vec3& v) { return json::array({number(v.x), number(v.y), number(v.z)}); }

// A path of the source file as the reader resolves it (relative to the file's folder; asset: paths move with the
// asset folder and stay as they are).
void makeAbsolute(json& value, const fs::path& folder) {
  if (!value.is_string()) return;
  const std::string path = value.get<std::string>();
  if (path.rfind("asset:", 0) == 0 || fs::path(path).is_absolute()) return;
  value = fs::absolute(folder / path).lexically_normal().string();
}

json cameraBlock(const Camera& c) {
  json block = {{"position", vec3(c.position)}, {"target", vec3(c.target)}, {"up", vec3(c.up)},
                {"near", number(c.nearPlane)}, {"far", number(c.farPlane)}};
  if (c.orthographic) {
    block["ortho_half_height"] = number(c.orthoHalfHeight);
  } else {
    block["fov_y_deg"] = number(c.fovYDeg);
  }
  return block;
}

json environmentBlock(const std::optional<EnvironmentDesc>& environment) {
  if (!environment) return "none";
  json e;
  if (!environment->file.empty()) {
    e["file"] = fs::absolute(environment->file).lexically_normal().string();
  } else {
    const SkyParams& s = environment->sky;
    e["sky"] = {{"zenith", vec3(s.zenith)},
                {"horizon", vec3(s.horizon)},
                {"ground", vec3(s.ground)},
                {"sun_direction", vec3(s.sunDirection)},
                {"sun_angular_radius_deg", number(s.sunAngularRadiusDeg)},
                {"sun_radiance", vec3(s.sunRadiance)}};
  }
  e["intensity"] = number(environment->intensity);
  e["rotation_deg"] = number(environment->rotationDeg);
  return e;
}

json lightBlock(const PointLight& l) {
  json out = {{"position", vec3(l.position)}, {"radius", number(l.radius)}, {"color", vec3(l.color)},
              {"luminous_power", number(l.luminousPower)}};
  if (l.spot) {
    out["type"] = "spot";
    out["direction"] = vec3(l.spot->direction);
    out["inner_angle_deg"] = number(glm::degrees(l.spot->innerAngle));
    out["outer_angle_deg"] = number(glm::degrees(l.spot->outerAngle));
  }
  return out;
}

// The file's own directional lights, then every point and spot light the viewer shows.
void listLights(json& document, const std::vector<PointLight>& lights) {
  json listed = json::array();
  if (document.contains("lights") && document["lights"].is_array()) {
    for (const json& l : document["lights"]) {
      if (l.is_object() && l.value("type", "") == "directional") listed.push_back(l);
    }
  }
  for (const PointLight& l : lights) listed.push_back(lightBlock(l));
  document["lights"] = std::move(listed);
  document.erase("random_lights");
}

bool close(float a, float b) { return std::abs(a - b) <= 1e-5f * std::max({1.0f, std::abs(a), std::abs(b)}); }
bool close(const glm::vec3& a, const glm::vec3& b) { return close(a.x, b.x) && close(a.y, b.y) && close(a.z, b.z); }

bool sameLights(const std::vector<PointLight>& a, const std::vector<PointLight>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    const PointLight &x = a[i], &y = b[i];
    if (!close(x.position, y.position) || !close(x.radius, y.radius) || !close(x.color, y.color) ||
        !close(x.luminousPower, y.luminousPower) || x.spot.has_value() != y.spot.has_value()) {
      return false;
    }
    if (x.spot && (!close(x.spot->direction, y.spot->direction) || !close(x.spot->innerAngle, y.spot->innerAngle) ||
                   !close(x.spot->outerAngle, y.spot->outerAngle))) {
      return false;
    }
  }
  return true;
}

void write(const std::string& path, const json& document) {
  writeOutputFile(path, [&](std::ostream& out) { out << document.dump(2) << '\n'; });
}

std::vector<PointLight> lightsOf(const std::string& path, const SceneParams& params) {
  return loadSceneFile(path, -1, params.uris, false, DefaultEnvironment::None).lights;
}

}  // namespace

void writeSceneSnapshot(const std::string& path, const SceneSnapshot& shot) {
  const bool builtin = isBuiltinScene(shot.sceneName);
  const fs::path source = builtin ? fs::path(builtinSceneDir()) / (shot.sceneName + ".json") : fs::path(shot.sceneName);
  const fs::path folder = source.parent_path();
  json document;
  if (source.extension() == ".json") {
    document = readJsonFile(source.string());
    if (document.contains("objects") && document["objects"].is_array()) {
      for (json& object : document["objects"]) {
        if (!object.is_object()) continue;
        if (object.contains("gltf")) makeAbsolute(object["gltf"], folder);
        if (object.contains("material") && object["material"].contains("base_color_texture")) {
          makeAbsolute(object["material"]["base_color_texture"], folder);
        }
      }
    }
    if (document.contains("random_lights") && document["random_lights"].is_object()) {
      // The count as --lights gave it, which counts the random lights alone, not those the file lists.
      if (shot.params.lights) document["random_lights"]["count"] = *shot.params.lights;
      if (shot.params.spotShare) document["random_lights"]["spot_share"] = number(*shot.params.spotShare);
    }
  } else {
    document["objects"] = json::array({{{"gltf", fs::absolute(source).lexically_normal().string()}}});
  }

  // With a physical exposure the file keeps one, at the EV100 that gives what the viewer shows with the scene's
  // multiplier; else the multiplier is the viewer's.
  json camera = cameraBlock(shot.camera);
  if (shot.scene.ev100 && shot.scene.exposure > 0.0f && shot.displayExposure > 0.0f) {
    camera["ev100"] = number(static_cast<float>(std::log2(shot.scene.exposure / (1.2 * shot.displayExposure))));
    document["exposure"] = number(shot.scene.exposure);
  } else {
    document["exposure"] = number(shot.displayExposure);
  }
  document["camera"] = std::move(camera);
  document["ambient"] = vec3(shot.scene.ambient);
  document["environment"] = environmentBlock(shot.scene.environment);

  write(path, document);
  if (sameLights(lightsOf(path, shot.params), shot.scene.lights)) return;
  // The built-in's rule made lights its file does not hold: list them. A glTF model's lights would then come twice.
  if (!shot.scene.gltfPlacedLights) {
    listLights(document, shot.scene.lights);
    write(path, document);
    if (sameLights(lightsOf(path, shot.params), shot.scene.lights)) return;
  }
  std::error_code ignored;
  fs::remove(path, ignored);
  throw SceneError(path + ": the scene's lights cannot be written as shown (the rule that made them is no field "
                          "of the file, and its glTF models bring lights of their own); not written");
}

}  // namespace pbr
