// What a glTF file holds that the renderer does not draw is named on stderr, one line per feature; values viewers
// read are read, and files with nothing to draw load as empty scenes.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/scene/builtin_scenes.hpp"
#include "core/scene/gltf_loader.hpp"
#include "core/scene/scene_json.hpp"
#include "tests/cli_util.hpp"
#include "tests/gltf_builder.hpp"

using nlohmann::json;
using pbr::test::CapturedStderr;
using pbr::test::GltfBuilder;
using pbr::test::TempDir;

TEST_CASE("gltf undrawn: morph targets, vertex colours, animations and other scenes need no warning, two notes") {
  const TempDir dir;
  GltfBuilder b = pbr::test::quadModel();
  json& primitive = b.doc["meshes"][0]["primitives"][0];
  const int positions = primitive["attributes"]["POSITION"];
  primitive["attributes"]["COLOR_0"] = b.addFloats(std::vector<float>(16, 0.5f), "VEC4");
  primitive["targets"] = {{{"POSITION", positions}}};
  b.doc["meshes"][0]["weights"] = {1.0};
  const float times[] = {0.0f, 1.0f};
  const float offsets[] = {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f};
  const int input = b.addView(times, sizeof times), output = b.addView(offsets, sizeof offsets);
  b.doc["accessors"].push_back({{"bufferView", input}, {"componentType", 5126}, {"count", 2}, {"type", "SCALAR"},
                                {"min", {0.0}}, {"max", {1.0}}});
  b.doc["accessors"].push_back({{"bufferView", output}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}});
  const int n = static_cast<int>(b.doc["accessors"].size());
  b.doc["animations"] = {{{"samplers", {{{"input", n - 2}, {"output", n - 1}}}},
                          {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}}};
  b.doc["scenes"].push_back({{"nodes", json::array()}});
  const std::string path = b.writeGltf(dir.path(), "features");
  CapturedStderr err;
  pbr::Scene scene;
  pbr::appendGltf(scene, path);
  CHECK(scene.objects.size() == 1);
  CHECK(err.text().empty());
  REQUIRE(scene.notes.size() == 2);
  CHECK(scene.notes[0] == "features.gltf has 1 animation: drawn at rest (--animation NAME|INDEX and --time SECONDS "
                          "pose it)");
  CHECK(scene.notes[1] == "features.gltf has 2 scenes: scene 0 is drawn (--gltf-scene N draws another)");
  // The other scene, chosen: it has no nodes; one past the last is refused by name.
  pbr::GltfSelection second;
  second.scene = 1;
  pbr::Scene other;
  pbr::appendGltf(other, path, glm::mat4(1.0f), {}, second);
  CHECK(other.objects.empty());
  second.scene = 2;
  pbr::Scene none;
  CHECK_THROWS_WITH_AS(pbr::appendGltf(none, path, glm::mat4(1.0f), {}, second),
                       (path + ": --gltf-scene 2: the file has 2 scenes").c_str(), pbr::SceneError);
}

TEST_CASE("gltf undrawn: a light range beyond the coordinate limit is read as no range, with one line") {
  const TempDir dir;
  GltfBuilder b = pbr::test::quadModel();
  // babylon.js for 3ds Max writes FLT_MAX for an "infinite" range.
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "spot"}, {"intensity", 100.0}, {"range", 3.4028234663852886e38}, {"spot", json::object()}}};
  b.doc["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  b.doc["scenes"][0]["nodes"].push_back(1);
  const std::string path = b.writeGltf(dir.path(), "infinite");
  CapturedStderr err;
  pbr::Scene scene;
  pbr::appendGltf(scene, path);
  REQUIRE(scene.lights.size() == 1);
  // The radius of a light without range: where 100 cd falls to the cutoff illuminance.
  CHECK(scene.lights[0].radius == doctest::Approx(std::sqrt(100.0 / pbr::kGltfLightCutoffIlluminance)));
  CHECK(err.text() == path + ": extensions.KHR_lights_punctual.lights[0].range: 3.40282e+38 is beyond the "
                             "coordinate limit 1e+12: read as no range (the light ends where it gives 0.01 lux)\n");
}

TEST_CASE("gltf undrawn: a file of points or of bare nodes loads as an empty scene with a note and the default rig") {
  const TempDir dir;
  GltfBuilder points = pbr::test::quadModel();
  points.doc["meshes"][0]["primitives"][0]["mode"] = 0;
  GltfBuilder nodes;
  nodes.addRootNode({{"name", "empty"}});
  for (const auto& [builder, name] : {std::make_pair(&points, "points"), std::make_pair(&nodes, "nodes")}) {
    CAPTURE(name);
    const std::string path = builder->writeGltf(dir.path(), name);
    CapturedStderr err;
    const pbr::Scene scene = pbr::loadSceneFile(path);
    CHECK(scene.objects.empty());
    CHECK(scene.lights.size() == 3);
    CHECK(std::find(scene.notes.begin(), scene.notes.end(),
                    "the file has no triangles to draw: the frame shows no geometry") != scene.notes.end());
    CHECK(err.text() == (builder == &points
                             ? path + ": meshes[0].primitives[0]: mode 0 (points or lines) is not drawn\n"
                             : std::string()));
  }
}

TEST_CASE("scene file: a scene with no light, environment, ambient light or emission says its frame is black") {
  const TempDir dir;
  const std::string camera = R"("camera": {"position": [0, 0, 5], "target": [0, 0, 0]})";
  const std::string dark = dir.write("dark.json", "{" + camera + R"(, "objects": [{"shape": "sphere"}]})");
  {
    CapturedStderr err;
    pbr::loadSceneFile(dark);
    CHECK(err.text() == dark + ": no lights, no environment, no ambient light and nothing emissive: the frame is "
                               "black\n");
  }
  // Any one of them is light enough to say nothing.
  for (const std::string& lit :
       {std::string(R"("ambient": 0.1)"),
        std::string(R"("lights": [{"position": [0, 2, 0], "radius": 5, "luminous_power": 100}])"),
        std::string(R"("objects": [{"shape": "sphere", "material": {"emissive": [1, 0, 0]}}])")}) {
    CAPTURE(lit);
    const std::string path = dir.write("lit.json", "{" + camera + ", " + lit + "}");
    CapturedStderr err;
    pbr::loadSceneFile(path);
    CHECK(err.text().empty());
  }
}

TEST_CASE("gltf leniency: a node with a matrix beside translation, rotation or scale uses the matrix, with one line") {
  const TempDir dir;
  GltfBuilder b = pbr::test::quadModel();
  b.doc["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 2, 0, 0, 1};  // moved 2 along x
  b.doc["nodes"][0]["translation"] = {0, 5, 0};
  const std::string path = b.writeGltf(dir.path(), "both");
  CapturedStderr err;
  pbr::Scene scene;
  pbr::appendGltf(scene, path);
  REQUIRE(scene.objects.size() == 1);
  CHECK(scene.objects[0].transform[3] == glm::vec4(2.0f, 0.0f, 0.0f, 1.0f));
  CHECK(err.text() == path + ": nodes[0].matrix: given with translation, rotation or scale; the matrix is used and "
                             "they are ignored (--strict refuses it)\n");
  pbr::Scene strict;
  CHECK_THROWS_WITH_AS(pbr::appendGltf(strict, path, glm::mat4(1.0f), pbr::UriPolicy{false, true}),
                       (path + ": nodes[0].matrix: given with translation, rotation or scale (the specification "
                               "allows one or the other)")
                           .c_str(),
                       pbr::SceneError);
}

TEST_CASE("gltf leniency: a light range of 0 is read as no range with one line, a string intensity refused") {
  const TempDir dir;
  GltfBuilder b = pbr::test::quadModel();
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 5.0}, {"range", 0}}};
  b.doc["nodes"].push_back({{"translation", {0, 1, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  b.doc["scenes"][0]["nodes"].push_back(1);
  const std::string path = b.writeGltf(dir.path(), "range0");
  CapturedStderr err;
  pbr::Scene scene;
  pbr::appendGltf(scene, path);
  REQUIRE(scene.lights.size() == 1);
  // As an absent range: the light ends where it gives the cutoff illuminance, well past 0.
  CHECK(scene.lights[0].radius > 1.0f);
  CHECK(err.text() == path + ": extensions.KHR_lights_punctual.lights[0].range: 0 read as no range, as three.js reads "
                             "it (the specification asks for a positive number; --strict refuses it)\n");
  pbr::Scene strict;
  CHECK_THROWS_WITH_AS(pbr::appendGltf(strict, path, glm::mat4(1.0f), pbr::UriPolicy{false, true}),
                       (path + ": extensions.KHR_lights_punctual.lights[0].range: must be positive (got 0)").c_str(),
                       pbr::SceneError);

  // tinygltf would read the string as its default intensity without a word.
  b.doc["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = "NaN";
  b.doc["extensions"]["KHR_lights_punctual"]["lights"][0].erase("range");
  const std::string nan = b.writeGltf(dir.path(), "nan");
  pbr::Scene refused;
  CHECK_THROWS_WITH_AS(pbr::appendGltf(refused, nan),
                       (nan + ": extensions.KHR_lights_punctual.lights[0].intensity: must be a number (got \"NaN\")")
                           .c_str(),
                       pbr::SceneError);
}

TEST_CASE("gltf leniency: a camera aspectRatio of 0 or below is named and the frame's own used, --strict refusing it") {
  const TempDir dir;
  GltfBuilder b = pbr::test::quadModel();
  b.doc["cameras"] = {{{"type", "perspective"},
                       {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 100.0}, {"aspectRatio", -1}}}}};
  b.doc["nodes"].push_back({{"translation", {0, 0, 5}}, {"camera", 0}});
  b.doc["scenes"][0]["nodes"].push_back(1);
  const std::string path = b.writeGltf(dir.path(), "aspect");
  CapturedStderr err;
  pbr::Scene scene;
  pbr::appendGltf(scene, path);
  CHECK(err.text().find(path + ": cameras[0].perspective.aspectRatio: -1 is not an aspect ratio; the frame's own is "
                               "used, as for any camera (--strict refuses it)\n") != std::string::npos);
  pbr::Scene strict;
  CHECK_THROWS_WITH_AS(pbr::appendGltf(strict, path, glm::mat4(1.0f), pbr::UriPolicy{false, true}),
                       (path + ": cameras[0].perspective.aspectRatio: must be positive (got -1)").c_str(),
                       pbr::SceneError);
  b.doc["cameras"][0]["perspective"]["aspectRatio"] = "1.5";
  const std::string text = b.writeGltf(dir.path(), "text");
  pbr::Scene refused;
  CHECK_THROWS_WITH_AS(pbr::appendGltf(refused, text),
                       (text + ": cameras[0].perspective.aspectRatio: must be a number (got \"1.5\")").c_str(),
                       pbr::SceneError);
}

TEST_CASE("gltf leniency: camera and spot light objects, accessor bounds and image types, each named in one line") {
  const TempDir dir;
  const auto errorOf = [](const std::string& path, bool strict = false) -> std::string {
    pbr::Scene scene;
    try {
      pbr::appendGltf(scene, path, glm::mat4(1.0f), pbr::UriPolicy{false, strict});
    } catch (const pbr::SceneError& e) {
      return e.what();
    }
    return "";
  };
  const auto warningOf = [](const std::string& path) {
    CapturedStderr err;
    pbr::Scene scene;
    pbr::appendGltf(scene, path);
    return err.text();
  };
  // A camera without its type, or without the object its type names; a field of view the renderer does not draw.
  GltfBuilder b = pbr::test::quadModel();
  b.doc["nodes"].push_back({{"translation", {0, 0, 5}}, {"camera", 0}});
  b.doc["scenes"][0]["nodes"].push_back(1);
  b.doc["cameras"] = {{{"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
  std::string path = b.writeGltf(dir.path(), "untyped");
  CHECK(errorOf(path) == path + ": cameras[0].type: is required (\"perspective\" or \"orthographic\")");
  b.doc["cameras"] = {{{"type", "orthographic"}}};
  path = b.writeGltf(dir.path(), "bare");
  CHECK(errorOf(path) == path + ": cameras[0].orthographic: is required for a camera of type \"orthographic\"");
  b.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.001}, {"znear", 0.1}}}}};
  path = b.writeGltf(dir.path(), "narrow");
  CHECK(errorOf(path) ==
        path + ": cameras[0].perspective.yfov: must be in [0.0174533, 3.12414] radians, 1 to 179 degrees (got 0.001)");

  // A spot light without its cone: the default one, as three.js reads it.
  GltfBuilder s = pbr::test::quadModel();
  s.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  s.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "spot"}, {"intensity", 5.0}}};
  s.doc["nodes"].push_back({{"translation", {0, 0, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  s.doc["scenes"][0]["nodes"].push_back(1);
  path = s.writeGltf(dir.path(), "spot");
  CHECK(warningOf(path) == path + ": extensions.KHR_lights_punctual.lights[0].spot: missing for a spot light: the "
                                  "default cone (inner angle 0, outer pi/4) is used, as three.js reads it (--strict "
                                  "refuses it)\n");
  pbr::Scene lit;
  pbr::appendGltf(lit, path);
  REQUIRE(lit.lights.size() == 1);
  REQUIRE(lit.lights[0].spot.has_value());
  CHECK(lit.lights[0].spot->innerAngle == 0.0f);
  CHECK(lit.lights[0].spot->outerAngle == doctest::Approx(0.25 * 3.14159265358979));
  CHECK(errorOf(path, true) == path + ": extensions.KHR_lights_punctual.lights[0].spot: is required for a spot light");

  // Accessor bounds of another form, and bounds that do not hold the positions (viewers that cull by them would
  // leave the quad out).
  GltfBuilder m = pbr::test::quadModel();
  const int position = m.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
  m.doc["accessors"][position]["min"] = "junk";
  m.doc["accessors"][position]["max"] = {1, 1, 0};
  path = m.writeGltf(dir.path(), "junk");
  CHECK(warningOf(path).find(path + ": accessors[" + std::to_string(position) +
                             "].min: \"junk\" is not 3 numbers, one per component; not used (--strict refuses it)\n") !=
        std::string::npos);
  CHECK(errorOf(path, true) ==
        path + ": accessors[" + std::to_string(position) + "].min: must be 3 numbers (got \"junk\")");
  m.doc["accessors"][position]["min"] = {5, 5, 5};
  m.doc["accessors"][position]["max"] = {6, 6, 6};
  path = m.writeGltf(dir.path(), "off");
  CHECK(warningOf(path) == path + ": accessors[" + std::to_string(position) +
                               "].min/max (meshes[0].primitives[0].attributes.POSITION): [5, 5, 5] to [6, 6, 6] do not "
                               "hold the positions, [-1, -1, 0] to [1, 1, 0], which are drawn (--strict refuses it)\n");

  // An image whose mimeType names another format than its bytes: decoded as what the bytes are.
  GltfBuilder t = pbr::test::quadModel();
  const int texture = t.addPngTexture(dir.path(), "red.png", pbr::test::solidImage(2, 2, {255, 0, 0, 255}));
  t.doc["images"][0]["mimeType"] = "image/jpeg";
  t.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}}}}};
  t.doc["meshes"][0]["primitives"][0]["material"] = 0;
  path = t.writeGltf(dir.path(), "mime");
  CHECK(warningOf(path) == path + ": images[0].mimeType: \"image/jpeg\", but the bytes are image/png, decoded as such "
                                  "(--strict refuses it)\n");
  CHECK(errorOf(path, true) == path + ": images[0].mimeType: \"image/jpeg\", but the bytes are image/png");
}

TEST_CASE("json: a NUL byte in a scene or glTF file is refused, a GLB JSON chunk padded with NULs read as spaces") {
  const TempDir dir;
  const std::string text = R"({"camera": {"position": [0, 2, 5], "target": [0, 0, 0]}})";
  const std::string scene = dir.write("nul.json", text + std::string(1, '\0'));
  CHECK_THROWS_WITH_AS(pbr::loadSceneFile(scene), (scene + ":1:57: a NUL byte, which JSON text cannot hold").c_str(),
                       pbr::SceneError);
  // The GLB's JSON chunk grows by four NUL bytes.
  const std::string glb = pbr::test::quadModel().writeGlb(dir.path(), "padded");
  std::string bytes = pbr::test::readFile(glb);
  const auto word = [&](size_t at) {
    uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = v << 8 | uint32_t(uint8_t(bytes[at + size_t(i)]));
    return v;
  };
  const auto setWord = [&](size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes[at + size_t(i)] = char(v >> (8 * i));
  };
  const uint32_t jsonLength = word(12);
  bytes.insert(20 + jsonLength, std::string(4, '\0'));
  setWord(12, jsonLength + 4);
  setWord(8, word(8) + 4);
  const std::string padded = dir.write("padded.glb", bytes);
  CapturedStderr err;
  pbr::Scene loaded;
  pbr::appendGltf(loaded, padded);
  CHECK(loaded.objects.size() == 1);
  CHECK(err.text() == padded + ": the JSON chunk is padded with NUL bytes, read as the spaces the specification asks "
                               "for (--strict refuses it)\n");
}

TEST_CASE("gltf undrawn: a primitive whose triangles all have zero area is named: it draws nothing") {
  const TempDir dir;
  // The quad's four corners on one line (x = y, z = 0), then its indices all one vertex.
  GltfBuilder line = pbr::test::quadModel();
  const int position = line.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
  const std::vector<float> colinear = {-1, -1, 0, 0, 0, 0, 1, 1, 0, 2, 2, 0};
  line.doc["accessors"][position]["bufferView"] = line.addView(colinear.data(), colinear.size() * sizeof(float));
  line.doc["accessors"][position]["min"] = {-1, -1, 0};
  line.doc["accessors"][position]["max"] = {2, 2, 0};
  std::string path = line.writeGltf(dir.path(), "line");
  {
    CapturedStderr err;
    pbr::Scene scene;
    pbr::appendGltf(scene, path);
    CHECK(err.text() == path + ": meshes[0].primitives[0]: its 2 triangles all have zero area (repeated indices, or "
                               "positions in one point or line): it draws nothing\n");
  }
  GltfBuilder point = pbr::test::quadModel();
  point.doc["meshes"][0]["primitives"][0]["indices"] = point.addIndices({2, 2, 2});
  path = point.writeGltf(dir.path(), "point");
  CapturedStderr err;
  pbr::Scene scene;
  pbr::appendGltf(scene, path);
  CHECK(err.text() == path + ": meshes[0].primitives[0]: its triangle has zero area (repeated indices, or positions "
                             "in one point or line): it draws nothing\n");
}

TEST_CASE("gltf errors: required objects tinygltf refused in its own words are named by their path") {
  const TempDir dir;
  const auto errorOf = [&](const std::function<void(GltfBuilder&)>& change, const std::string& name) -> std::string {
    GltfBuilder b = pbr::test::quadModel();
    change(b);
    const std::string path = b.writeGltf(dir.path(), name);
    try {
      pbr::Scene scene;
      pbr::appendGltf(scene, path);
    } catch (const pbr::SceneError& e) {
      const std::string message = e.what();
      CHECK(message.rfind(path + ": ", 0) == 0);
      return message.substr(path.size() + 2);
    }
    return "";
  };
  CHECK(errorOf([](GltfBuilder& b) { b.doc.erase("asset"); }, "asset") ==
        "asset: is required (an object with the glTF version)");
  CHECK(errorOf([](GltfBuilder& b) { b.doc["images"] = {json::object()}; }, "image") ==
        "images[0]: needs a uri or a bufferView");
  CHECK(errorOf([](GltfBuilder& b) { b.doc["skins"] = {json::object()}; }, "skin") ==
        "skins[0].joints: is required (the skin's joint nodes)");
  CHECK(errorOf([](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0].erase("attributes"); }, "attributes") ==
        "meshes[0].primitives[0].attributes: is required (at least POSITION)");
  CHECK(errorOf(
            [](GltfBuilder& b) {
              b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
              b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {json::object()};
            },
            "light") == "extensions.KHR_lights_punctual.lights[0].type: is required (\"point\", \"spot\" or "
                        "\"directional\")");
  // A mesh without primitives draws nothing, as three.js draws it, said in a warning; --strict refuses it.
  GltfBuilder empty = pbr::test::quadModel();
  empty.doc["meshes"].push_back({{"primitives", json::array()}});
  empty.doc["nodes"].push_back({{"mesh", 1}});
  empty.doc["scenes"][0]["nodes"].push_back(1);
  const std::string path = empty.writeGltf(dir.path(), "empty");
  CapturedStderr err;
  pbr::Scene scene;
  pbr::appendGltf(scene, path);
  CHECK(scene.objects.size() == 1);
  CHECK(err.text() == path + ": meshes[1].primitives: none (the specification asks for at least one): the mesh draws "
                             "nothing (--strict refuses it)\n");
}
