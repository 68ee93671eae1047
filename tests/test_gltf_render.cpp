// glTF models through the whole renderer: the sample assets render lit and textured, and small files written here
// check each material input (alpha mask, normal map, emission, occlusion, double-sided, texture transform) against
// what the test knows it wrote.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/assets.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/gltf_loader.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/gltf_builder.hpp"
#include "tests/render_util.hpp"

using nlohmann::json;
using pbr::test::GltfBuilder;
using pbr::test::maxByteDifference;
using pbr::test::meanAbsDifference;
using pbr::test::QuadSpec;
using pbr::test::TempDir;

namespace {

constexpr glm::ivec2 kSize{192, 108};

pbr::FrameOptions options(pbr::ShadingModel model = pbr::ShadingModel::Pbr) {
  pbr::FrameOptions o;
  o.model = model;
  return o;
}

const float* pixel(const pbr::ImageRgbaF& image, glm::ivec2 p) { return image.at(p.x, p.y); }
glm::vec3 rgb(const pbr::ImageRgbaF& image, glm::ivec2 p) {
  const float* v = pixel(image, p);
  return {v[0], v[1], v[2]};
}

// Frame positions on the centre row: the centre, and a quarter of the quad's width left and right of it. The
// quad of quadScene spans about 38 pixels either side of the centre.
const glm::ivec2 kCentre{kSize.x / 2, kSize.y / 2};
const glm::ivec2 kLeft{kSize.x / 2 - 19, kSize.y / 2};
const glm::ivec2 kRight{kSize.x / 2 + 19, kSize.y / 2};

// The quad files of gltf_builder seen head-on from +Z, 3 units away.
pbr::Scene quadScene(const std::string& path) {
  pbr::Scene scene;
  scene.camera.position = {0.0f, 0.0f, 3.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.fovYDeg = 50.0f;
  scene.camera.nearPlane = 0.1f;
  scene.camera.farPlane = 20.0f;
  pbr::appendGltf(scene, path);
  return scene;
}

// A model framed from the front-right and above, lit by a white key light and a dimmer fill, with some ambient.
pbr::Scene modelScene(const std::string& path) {
  pbr::Scene scene;
  const pbr::Bounds b = pbr::appendGltf(scene, path);
  const glm::vec3 centre = 0.5f * (b.min + b.max);
  const float radius = 0.5f * glm::length(b.max - b.min);
  const glm::vec3 view = glm::normalize(glm::vec3(0.4f, 0.3f, 1.0f));
  scene.camera.position = centre + view * radius * 2.0f;
  scene.camera.target = centre;
  scene.camera.fovYDeg = 45.0f;
  scene.camera.nearPlane = 0.1f * radius;
  scene.camera.farPlane = 10.0f * radius;
  scene.ambient = glm::vec3(0.3f);
  const float power = 1500.0f * radius * radius;  // the same illuminance at any model scale
  scene.lights.push_back({centre + glm::vec3(1.5f, 2.0f, 2.5f) * radius, 20.0f * radius, glm::vec3(1.0f), power});
  scene.lights.push_back(
      {centre + glm::vec3(-2.5f, 0.5f, 1.5f) * radius, 20.0f * radius, glm::vec3(0.6f, 0.7f, 1.0f), 0.5f * power});
  return scene;
}

struct PixelStats {
  size_t covered = 0;               // pixels that saw geometry (non-zero radiance; empty pixels are exactly 0)
  double mean = 0.0, stddev = 0.0;  // 8-bit luma of covered pixels
  size_t distinctColors = 0;
};

PixelStats stats(const pbr::test::RenderedFrame& f) {
  PixelStats s;
  std::set<uint32_t> colors;
  double sum = 0.0, sum2 = 0.0;
  for (int y = 0; y < f.hdr.height; ++y) {
    for (int x = 0; x < f.hdr.width; ++x) {
      const float* h = f.hdr.at(x, y);
      if (h[0] == 0.0f && h[1] == 0.0f && h[2] == 0.0f) continue;
      const uint8_t* l = &f.ldr.pixels[(static_cast<size_t>(y) * f.ldr.width + x) * 4];
      const double luma = 0.2126 * l[0] + 0.7152 * l[1] + 0.0722 * l[2];
      sum += luma;
      sum2 += luma * luma;
      colors.insert(uint32_t(l[0]) << 16 | uint32_t(l[1]) << 8 | l[2]);
      ++s.covered;
    }
  }
  if (s.covered) {
    s.mean = sum / s.covered;
    s.stddev = std::sqrt(std::max(0.0, sum2 / s.covered - s.mean * s.mean));
  }
  s.distinctColors = colors.size();
  return s;
}

// The scene with every material map removed: what the model would look like untextured.
pbr::Scene untextured(pbr::Scene scene) {
  for (pbr::SceneObject& o : scene.objects) {
    o.material.baseColorTexture = o.material.metallicRoughnessTexture = o.material.normalTexture = -1;
    o.material.occlusionTexture = o.material.emissiveTexture = -1;
  }
  scene.textures.clear();
  return scene;
}

// A file with one quad of `material` (its textures written as PNGs into `dir`), at the origin unless `node` says
// otherwise.
std::string materialQuad(const TempDir& dir, const std::string& name, json material, QuadSpec spec = {},
                         const std::vector<std::pair<std::string, pbr::ImageRgba8>>& images = {},
                         json node = json::object()) {
  GltfBuilder b;
  for (const auto& [file, image] : images) b.addPngTexture(dir.path(), file, image);
  spec.material = b.addMaterial(material);
  node["mesh"] = pbr::test::addQuad(b, spec);
  b.addRootNode(node);
  return b.writeGltf(dir.path(), name);
}

}  // namespace

TEST_CASE("gltf render: DamagedHelmet, Suzanne and BoxTextured render lit and textured") {
  PBR_REQUIRE_GL();
  struct Case {
    const char* file;
    size_t minColors;
  };
  for (const Case& c :
       {Case{"DamagedHelmet/glTF-Binary/DamagedHelmet.glb", 1000}, Case{"Suzanne/glTF/Suzanne.gltf", 300},
        Case{"BoxTextured/glTF-Embedded/BoxTextured.gltf", 300}}) {
    const std::string file = c.file;
    CAPTURE(file);
    const pbr::Scene scene = modelScene(pbr::assetPath(c.file));
    const pbr::test::RenderedFrame textured = pbr::test::renderScene(scene, kSize, options(), 1);
    const pbr::test::RenderedFrame plain = pbr::test::renderScene(untextured(scene), kSize, options(), 1);
    const PixelStats s = stats(textured);
    MESSAGE(c.file << ": " << s.covered << " covered pixels, luma mean " << s.mean << ", stddev " << s.stddev << ", "
                   << s.distinctColors << " colours; mean |textured - untextured| "
                   << meanAbsDifference(textured.ldr, plain.ldr));
    CHECK(s.covered > static_cast<size_t>(kSize.x * kSize.y / 8));
    CHECK(s.mean > 25.0);    // lit, not black
    CHECK(s.stddev > 12.0);  // not flat
    CHECK(s.distinctColors >= c.minColors);
    CHECK(meanAbsDifference(textured.ldr, plain.ldr) > 3.0);  // the textures show
  }
}

TEST_CASE("gltf render: DamagedHelmet as .gltf and as .glb gives the same frame") {
  PBR_REQUIRE_GL();
  const pbr::test::RenderedFrame a =
      pbr::test::renderScene(modelScene(pbr::assetPath("DamagedHelmet/glTF/DamagedHelmet.gltf")), kSize, options(), 1);
  const pbr::test::RenderedFrame b = pbr::test::renderScene(
      modelScene(pbr::assetPath("DamagedHelmet/glTF-Binary/DamagedHelmet.glb")), kSize, options(), 1);
  CHECK(maxByteDifference(a.ldr, b.ldr) <= 1);
  CHECK(stats(a).covered > 0);
}

TEST_CASE("gltf render: the helmet scene is textured and emissive, and clustered equals brute force") {
  PBR_REQUIRE_GL();
  pbr::SceneParams params;
  params.lights = 24;
  const pbr::Scene scene = pbr::makeBuiltinScene("helmet", params);
  CHECK(scene.lights.size() == 24);
  CHECK(pbr::makeBuiltinScene("helmet").lights.size() == 16);
  pbr::FrameOptions clustered = options(), brute = options();
  brute.culling = pbr::Culling::None;
  for (const pbr::ShadingModel model : {pbr::ShadingModel::Pbr, pbr::ShadingModel::BlinnPhong}) {
    clustered.model = brute.model = model;
    const pbr::test::RenderedFrame c = pbr::test::renderScene(scene, {160, 90}, clustered, 2);
    const pbr::test::RenderedFrame b = pbr::test::renderScene(scene, {160, 90}, brute, 1);
    CHECK(c.hdr.pixels == b.hdr.pixels);
    CHECK(stats(c).stddev > 12.0);
  }
}

TEST_CASE("gltf render: alpha MASK discards pixels below the cutoff, OPAQUE ignores alpha") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  // Left texel alpha 0.2, right texel alpha 1, sampled without filtering.
  pbr::ImageRgba8 image = pbr::test::solidImage(2, 1, {255, 255, 255, 255});
  image.pixels[3] = 51;
  for (const std::string mode : {"MASK", "OPAQUE"}) {
    CAPTURE(mode);
    const json material = {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.0}}},
                           {"alphaMode", mode}};
    const std::string path = materialQuad(dir, "alpha_" + mode, material, {}, {{"half.png", image}});
    // Nearest filtering keeps the two halves apart; BoxTextured covers the filtered path.
    json doc = json::parse(pbr::test::readFile(path));
    doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33071}}};
    doc["textures"][0]["sampler"] = 0;
    std::ofstream(path) << doc.dump();
    pbr::Scene scene = quadScene(path);
    scene.lights.push_back({{0.0f, 0.0f, 2.0f}, 10.0f, glm::vec3(1.0f), 200.0f});
    const pbr::test::RenderedFrame f = pbr::test::renderScene(scene, kSize, options(), 1);
    CHECK(rgb(f.hdr, kRight).x > 0.05f);
    if (mode == "MASK") {
      CHECK(rgb(f.hdr, kLeft) == glm::vec3(0.0f));  // the background: nothing was drawn
    } else {
      CHECK(rgb(f.hdr, kLeft).x > 0.05f);
    }
  }
}

TEST_CASE("gltf render: a normal map tilts the shading normal along the tangent frame") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  // Tangent-space normals tilted 30 degrees towards +X (+u) and towards +Y (up the image).
  const float s = std::sin(glm::radians(30.0f)), c = std::cos(glm::radians(30.0f));
  const auto encode = [](float v) { return static_cast<uint8_t>(std::lround((v * 0.5f + 0.5f) * 255.0f)); };
  const pbr::ImageRgba8 towardsU = pbr::test::solidImage(2, 2, {encode(s), encode(0.0f), encode(c), 255});
  const pbr::ImageRgba8 towardsUp = pbr::test::solidImage(2, 2, {encode(0.0f), encode(s), encode(c), 255});
  const json flatMaterial = {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}}};
  json mappedMaterial = flatMaterial;
  mappedMaterial["normalTexture"] = {{"index", 0}};

  // The image upright (u along +x, up the image along +y) or mirrored (u along -x), tangents stored or generated.
  struct Layout {
    const char* name;
    bool mirrored, storedTangents;
  };
  for (const Layout& layout : {Layout{"upright, stored", false, true}, Layout{"upright, generated", false, false},
                               Layout{"mirrored, stored", true, true}, Layout{"mirrored, generated", true, false}}) {
    const std::string name = layout.name;
    CAPTURE(name);
    QuadSpec spec;
    spec.tangents = layout.storedTangents;
    if (layout.mirrored) {
      spec.uvFromXy = glm::mat2(-0.5f, 0.0f, 0.0f, -0.5f);
      spec.tangent = {-1.0f, 0.0f, 0.0f, -1.0f};
    }
    const glm::vec3 uDirection(layout.mirrored ? -1.0f : 1.0f, 0.0f, 0.0f);
    const std::string tag = std::to_string(layout.mirrored) + std::to_string(layout.storedTangents);
    const std::string flatFile = materialQuad(dir, "flat" + tag, flatMaterial, spec);
    for (const auto& [what, image, towards] :
         {std::tuple<const char*, pbr::ImageRgba8, glm::vec3>{"+u", towardsU, uDirection},
          {"up", towardsUp, glm::vec3(0.0f, 1.0f, 0.0f)}}) {
      const std::string tilt = what;
      CAPTURE(tilt);
      const std::string mappedFile = materialQuad(dir, std::string("mapped") + tag + (what[0] == '+' ? "u" : "v"),
                                                  mappedMaterial, spec, {{"n.png", image}});
      // A light on the side the normal leans to lights the mapped quad more than the flat one; on the other
      // side, less.
      for (const float side : {1.0f, -1.0f}) {
        CAPTURE(side);
        const pbr::PointLight light{towards * (1.5f * side) + glm::vec3(0.0f, 0.0f, 1.0f), 10.0f, glm::vec3(1.0f),
                                    300.0f};
        pbr::Scene flat = quadScene(flatFile), mapped = quadScene(mappedFile);
        flat.lights = mapped.lights = {light};
        const float flatValue = rgb(pbr::test::renderScene(flat, kSize, options(), 1).hdr, kCentre).x;
        const float mappedValue = rgb(pbr::test::renderScene(mapped, kSize, options(), 1).hdr, kCentre).x;
        REQUIRE(flatValue > 0.0f);
        if (side > 0.0f) {
          CHECK(mappedValue > 1.3f * flatValue);
        } else {
          CHECK(mappedValue < 0.7f * flatValue);
        }
      }
    }
  }
}

TEST_CASE("gltf render: emission shows with no lights and no ambient, in both shading models") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const uint8_t code = 188;  // sRGB 188 decodes to 0.5029
  const double decoded = std::pow((code / 255.0 + 0.055) / 1.055, 2.4);
  const json material = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.0, 0.0, 0.0, 1.0}}}},
                         {"emissiveFactor", {1.0, 0.5, 0.25}},
                         {"emissiveTexture", {{"index", 0}}},
                         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2.0}}}}}};
  const std::string path =
      materialQuad(dir, "emissive", material, {}, {{"e.png", pbr::test::solidImage(2, 2, {code, code, code, 255})}});
  const pbr::Scene scene = quadScene(path);
  REQUIRE(scene.lights.empty());
  REQUIRE(scene.ambient == glm::vec3(0.0f));
  const glm::vec3 expected = glm::vec3(2.0f, 1.0f, 0.5f) * static_cast<float>(decoded);
  for (const pbr::ShadingModel model : {pbr::ShadingModel::Pbr, pbr::ShadingModel::BlinnPhong}) {
    const pbr::test::RenderedFrame f = pbr::test::renderScene(scene, kSize, options(model), 1);
    // Blinn-Phong frames are clamped to [0, 1].
    const glm::vec3 want = model == pbr::ShadingModel::Pbr ? expected : glm::min(expected, glm::vec3(1.0f));
    const glm::vec3 got = rgb(f.hdr, kCentre);
    MESSAGE("emitted " << got.x << " " << got.y << " " << got.z);
    for (int ch = 0; ch < 3; ++ch) CHECK(got[ch] == doctest::Approx(want[ch]).epsilon(0.01));
    CHECK(rgb(f.hdr, {2, 2}) == glm::vec3(0.0f));  // outside the quad
  }
}

TEST_CASE("gltf render: occlusion scales the ambient term only") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const pbr::ImageRgba8 black = pbr::test::solidImage(2, 2, {0, 0, 0, 255});
  const auto occluded = [&](double strength, const std::string& name) {
    const json material = {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
                           {"occlusionTexture", {{"index", 0}, {"strength", strength}}}};
    pbr::Scene scene = quadScene(materialQuad(dir, name, material, {}, {{"ao.png", black}}));
    scene.ambient = glm::vec3(0.5f);
    return scene;
  };
  pbr::Scene open = quadScene(materialQuad(dir, "open", {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}}));
  open.ambient = glm::vec3(0.5f);
  for (const pbr::ShadingModel model : {pbr::ShadingModel::Pbr, pbr::ShadingModel::BlinnPhong}) {
    const float ambient = rgb(pbr::test::renderScene(open, kSize, options(model), 1).hdr, kCentre).x;
    const float full = rgb(pbr::test::renderScene(occluded(1.0, "ao1"), kSize, options(model), 1).hdr, kCentre).x;
    const float half = rgb(pbr::test::renderScene(occluded(0.5, "ao05"), kSize, options(model), 1).hdr, kCentre).x;
    MESSAGE("ambient " << ambient << ", occlusion 0: " << full << ", strength 0.5: " << half);
    REQUIRE(ambient > 0.0f);
    CHECK(full == 0.0f);
    // Occlusion 1 + 0.5 (0 - 1) = 0.5, stored as 8 bits (128/255).
    CHECK(half / ambient == doctest::Approx(128.0 / 255.0).epsilon(0.01));
  }
  // Direct light is not occluded.
  pbr::Scene lit = occluded(1.0, "ao_lit");
  lit.ambient = glm::vec3(0.0f);
  lit.lights.push_back({{0.0f, 0.0f, 2.0f}, 10.0f, glm::vec3(1.0f), 200.0f});
  CHECK(rgb(pbr::test::renderScene(lit, kSize, options(), 1).hdr, kCentre).x > 0.05f);
}

TEST_CASE("gltf render: double-sided quads show their back lit from behind, mirrored nodes keep their faces") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const json turned = {{"rotation", {0.0, 1.0, 0.0, 0.0}}};  // 180 degrees about Y: the back faces the camera
  const pbr::PointLight light{{0.0f, 0.0f, 2.0f}, 10.0f, glm::vec3(1.0f), 200.0f};
  for (const bool doubleSided : {false, true}) {
    CAPTURE(doubleSided);
    const json material = {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}, {"doubleSided", doubleSided}};
    pbr::Scene scene = quadScene(materialQuad(dir, "back" + std::to_string(doubleSided), material, {}, {}, turned));
    scene.lights = {light};
    const glm::vec3 centre = rgb(pbr::test::renderScene(scene, kSize, options(), 1).hdr, kCentre);
    if (doubleSided) {
      // The flipped normal faces the light, which stands on the camera's side.
      CHECK(centre.x > 0.05f);
    } else {
      CHECK(centre == glm::vec3(0.0f));  // culled
    }
  }
  // Scale -1 along x mirrors the quad onto itself; its front must stay front (the winding flips with it).
  const json material = {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}};
  pbr::Scene plain = quadScene(materialQuad(dir, "plain", material));
  pbr::Scene mirrored = quadScene(materialQuad(dir, "mirrored", material, {}, {}, {{"scale", {-1.0, 1.0, 1.0}}}));
  plain.lights = mirrored.lights = {light};
  const float a = rgb(pbr::test::renderScene(plain, kSize, options(), 1).hdr, kCentre).x;
  const float b = rgb(pbr::test::renderScene(mirrored, kSize, options(), 1).hdr, kCentre).x;
  CHECK(a > 0.05f);
  CHECK(b == doctest::Approx(a).epsilon(1e-3));
}

TEST_CASE("gltf render: KHR_texture_transform moves, turns and scales the base colour and emissive maps") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  // 4 x 4 texels of distinct colours, sampled without filtering and repeated.
  const auto texel = [](glm::ivec2 t) { return glm::u8vec4(85 * t.x, 85 * t.y, 255 * ((t.x + t.y) % 2), 255); };
  pbr::ImageRgba8 image{4, 4, {}};
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const glm::u8vec4 c = texel({x, y});
      image.pixels.insert(image.pixels.end(), {c.x, c.y, c.z, c.w});
    }
  }
  struct Transform {
    glm::vec2 offset;
    float rotation;
    glm::vec2 scale;
    json asJson() const {
      return {{"offset", {offset.x, offset.y}}, {"rotation", rotation}, {"scale", {scale.x, scale.y}}};
    }
    // The specification's T R S (u, v, 1), R turning +u towards -v (glTF issue #1563).
    glm::vec2 operator()(glm::vec2 uv) const {
      const float c = std::cos(rotation), s = std::sin(rotation);
      const glm::vec2 scaled = uv * scale;
      return offset + glm::vec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y);
    }
  };
  const Transform baseColor{{0.0f, 0.5f}, glm::half_pi<float>(), {0.5f, 1.5f}};
  const Transform emissive{{0.25f, 0.5f}, 0.0f, {1.0f, 1.0f}};  // samples one texel right, two down
  const Transform none{{0.0f, 0.0f}, 0.0f, {1.0f, 1.0f}};
  const Transform otherWay{baseColor.offset, -baseColor.rotation, baseColor.scale};
  const auto texelAt = [](glm::vec2 uv) { return glm::ivec2(glm::floor(glm::fract(uv) * 4.0f)); };

  const auto textureInfo = [](const Transform& t) {
    return json{{"index", 0}, {"extensions", {{"KHR_texture_transform", t.asJson()}}}};
  };
  const json material = {{"pbrMetallicRoughness", {{"baseColorTexture", textureInfo(baseColor)}}},
                         {"emissiveFactor", {1.0, 1.0, 1.0}},
                         {"emissiveTexture", textureInfo(emissive)}};
  const std::string path = materialQuad(dir, "transformed", material, {}, {{"texels.png", image}});
  json doc = json::parse(pbr::test::readFile(path));
  doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 10497}, {"wrapT", 10497}}};
  doc["textures"][0]["sampler"] = 0;
  doc["extensionsUsed"] = doc["extensionsRequired"] = {"KHR_texture_transform"};
  std::ofstream(path) << doc.dump();
  const pbr::Scene scene = quadScene(path);
  REQUIRE(scene.lights.empty());  // the HDR frame is the emission alone
  pbr::FrameOptions baseColorView = options();
  baseColorView.debug = pbr::DebugChannel::BaseColor;
  const pbr::test::RenderedFrame f = pbr::test::renderScene(scene, kSize, baseColorView, 1);
  const auto decode = [](uint8_t code) {
    const double c = code / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };

  // Pixels 9.5 pixels either side of the frame's centre, where the quad's uv is 0.375 or 0.625 give or take 0.002:
  // the centres of texels 1 and 2. Both transforms take these points a quarter of a texel or more from any texel's
  // edge, so that no rounding of the frame can change the texel.
  bool notIdentity = false, notOtherWay = false;
  for (const glm::vec2 uv : {glm::vec2(0.375f, 0.375f), glm::vec2(0.625f, 0.375f), glm::vec2(0.375f, 0.625f),
                             glm::vec2(0.625f, 0.625f)}) {
    const glm::ivec2 p = kCentre + glm::ivec2(uv.x < 0.5f ? -10 : 9, uv.y < 0.5f ? -10 : 9);  // v down the frame
    CAPTURE(uv.x);
    CAPTURE(uv.y);
    const glm::ivec2 base = texelAt(baseColor(uv));
    notIdentity |= base != texelAt(none(uv));
    notOtherWay |= base != texelAt(otherWay(uv));
    const uint8_t* shown = &f.ldr.pixels[(static_cast<size_t>(p.y) * f.ldr.width + p.x) * 4];
    const glm::u8vec4 want = texel(base);
    for (int ch = 0; ch < 3; ++ch) CHECK(std::abs(int(shown[ch]) - int(want[ch])) <= 2);
    const glm::u8vec4 glow = texel(texelAt(emissive(uv)));
    const glm::vec3 got = rgb(f.hdr, p);
    for (int ch = 0; ch < 3; ++ch) CHECK(got[ch] == doctest::Approx(decode(glow[ch])).epsilon(0.01));
  }
  // The points would catch the transform left out or the rotation turned the other way.
  CHECK(notIdentity);
  CHECK(notOtherWay);
}

TEST_CASE("gltf render: a byteStride of 0 is read as tightly packed with a warning, and refused with --strict") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const json material = {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}};
  // The same quad with its positions' view declaring a stride of 12 (tightly packed VEC3 floats) and of 0.
  const auto withStride = [&](int stride) {
    const std::string path = materialQuad(dir, "stride" + std::to_string(stride), material);
    json doc = json::parse(pbr::test::readFile(path));
    const int positions = doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
    doc["bufferViews"][doc["accessors"][positions]["bufferView"].get<int>()]["byteStride"] = stride;
    std::ofstream(path) << doc.dump();
    return path;
  };
  const std::string explicitStride = withStride(12), zeroStride = withStride(0);
  pbr::Scene reference = quadScene(explicitStride), lenient = quadScene(zeroStride);
  for (pbr::Scene* s : {&reference, &lenient}) s->lights.push_back({{0.0f, 0.0f, 2.0f}, 10.0f, glm::vec3(1.0f), 200.0f});
  const pbr::test::RenderedFrame a = pbr::test::renderScene(reference, kSize, options(), 1);
  const pbr::test::RenderedFrame b = pbr::test::renderScene(lenient, kSize, options(), 1);
  CHECK(rgb(a.hdr, kCentre).x > 0.05f);
  CHECK(a.hdr.pixels == b.hdr.pixels);
  // The command line says what it assumed, and --strict refuses the file with the specification's range.
  const pbr::test::PbrRun run = pbr::test::runPbr(dir, {"render", "--scene", zeroStride, "--size", "32x18",
                                                        "--frames", "1", "--out", dir.file("lenient.png")});
  CHECK(run.exitCode == 0);
  CHECK(run.err.find("bufferViews[0].byteStride: 0 read as tightly packed") != std::string::npos);
  const pbr::test::PbrRun strict = pbr::test::runPbr(dir, {"render", "--strict", "--scene", zeroStride, "--size",
                                                           "32x18", "--frames", "1", "--out", dir.file("strict.png")});
  CHECK(strict.exitCode == 1);
  CHECK(strict.err.find("bufferViews[0].byteStride: must be an integer in [4, 252] (got 0)") != std::string::npos);
}

TEST_CASE("gltf render: missing and undecodable textures are drawn as their neutral value, one warning per file") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const json plain = {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"baseColorFactor", {0.8, 0.5, 0.3, 1.0}}}}};
  json textured = plain;
  textured["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  textured["normalTexture"] = {{"index", 1}};
  textured["occlusionTexture"] = {{"index", 2}};
  textured["emissiveTexture"] = {{"index", 3}};
  textured["emissiveFactor"] = {1.0, 1.0, 1.0};
  const pbr::ImageRgba8 grey = pbr::test::solidImage(4, 4, {100, 100, 100, 255});
  const std::string broken = materialQuad(dir, "broken", textured, {},
                                          {{"base.png", grey}, {"normal.png", grey}, {"occlusion.png", grey},
                                           {"emissive.png", grey}});
  // Three files gone, the fourth cut short.
  for (const char* file : {"base.png", "normal.png", "occlusion.png"}) std::filesystem::remove(dir.path() / file);
  std::filesystem::resize_file(dir.path() / "emissive.png", 40);
  // What the placeholders stand for: the factors alone, and a white emission map.
  json untextured = plain;
  untextured["emissiveFactor"] = {1.0, 1.0, 1.0};
  const std::string reference = materialQuad(dir, "reference", untextured);
  pbr::Scene expected = quadScene(reference), lenient = quadScene(broken);
  for (pbr::Scene* s : {&expected, &lenient}) s->lights.push_back({{0.0f, 0.0f, 2.0f}, 10.0f, glm::vec3(1.0f), 200.0f});
  const pbr::test::RenderedFrame a = pbr::test::renderScene(expected, kSize, options(), 1);
  const pbr::test::RenderedFrame b = pbr::test::renderScene(lenient, kSize, options(), 1);
  CHECK(rgb(a.hdr, kCentre).x > 0.05f);
  CHECK(a.hdr.pixels == b.hdr.pixels);

  const pbr::test::PbrRun run = pbr::test::runPbr(
      dir, {"render", "--scene", broken, "--size", "32x18", "--frames", "1", "--out", dir.file("lenient.png")});
  CHECK(run.exitCode == 0);
  CAPTURE(run.err);
  size_t warnings = 0;
  for (size_t at = run.err.find("drawn without it"); at != std::string::npos; at = run.err.find("drawn without it", at + 1))
    ++warnings;
  CHECK(warnings == 4);
  for (const char* line : {"images[0] ('base.png'): no such file", "images[1] ('normal.png'): no such file",
                           "images[2] ('occlusion.png'): no such file", "images[3] ('emissive.png'): cannot decode"}) {
    CHECK(run.err.find(line) != std::string::npos);
  }
  const pbr::test::PbrRun strict = pbr::test::runPbr(dir, {"render", "--strict", "--scene", broken, "--size",
                                                           "32x18", "--frames", "1", "--out", dir.file("strict.png")});
  CHECK(strict.exitCode == 1);
  CHECK(strict.err.find("images[0].uri: 'base.png'") != std::string::npos);
}
