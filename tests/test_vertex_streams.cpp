// glTF's optional vertex streams: COLOR_0 multiplies the base colour (float RGB and normalized unsigned-byte RGBA,
// checked per pixel against the colour the test interpolates itself), and TEXCOORD_1 places the maps whose texCoord
// is 1 (a base colour map and an occlusion map read through a mirrored second UV set).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/gltf_loader.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/gltf_builder.hpp"
#include "tests/render_util.hpp"

using nlohmann::json;
using pbr::test::GltfBuilder;
using pbr::test::TempDir;

namespace {

constexpr glm::ivec2 kSize{120, 90};
constexpr float kDistance = 3.0f, kFovY = 60.0f;

// The square (+-1, +-1) at z = 0 facing +Z: corners counter-clockwise from (-1, -1); TEXCOORD_0 maps it upright
// ((x + 1) / 2, (1 - y) / 2), TEXCOORD_1 mirrored left to right.
const std::vector<glm::vec2> kCorners = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};

// The corner colours of an affine field over the square, so that both triangles interpolate the same field.
glm::vec3 field(glm::vec2 p) { return {0.5f + 0.3f * p.x, 0.5f + 0.2f * p.y, 0.4f + 0.1f * p.x + 0.15f * p.y}; }

// A model of the square with `material`; `color` adds COLOR_0 ("VEC3" floats or "VEC4" normalized unsigned
// bytes, alpha 1) holding field() at the corners; `uv1` adds the mirrored TEXCOORD_1.
std::string square(const TempDir& dir, const std::string& name, const json& material, const std::string& color,
                   bool uv1, const std::vector<std::pair<std::string, pbr::ImageRgba8>>& images = {}) {
  GltfBuilder b;
  for (const auto& [file, image] : images) b.addPngTexture(dir.path(), file, image);
  if (!images.empty()) {
    b.doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}}};  // NEAREST: the halves stay sharp
    for (json& t : b.doc["textures"]) t["sampler"] = 0;
  }
  std::vector<float> positions, normals, uv0, uv1s, colors;
  std::vector<uint8_t> bytes;
  for (const glm::vec2& c : kCorners) {
    positions.insert(positions.end(), {c.x, c.y, 0.0f});
    normals.insert(normals.end(), {0.0f, 0.0f, 1.0f});
    const glm::vec2 uv((c.x + 1.0f) / 2.0f, (1.0f - c.y) / 2.0f);
    uv0.insert(uv0.end(), {uv.x, uv.y});
    uv1s.insert(uv1s.end(), {1.0f - uv.x, uv.y});
    const glm::vec3 f = field(c);
    colors.insert(colors.end(), {f.x, f.y, f.z});
    for (int k = 0; k < 3; ++k) bytes.push_back(static_cast<uint8_t>(std::lround(255.0f * f[k])));
    bytes.push_back(255);
  }
  json primitive = {{"attributes",
                     {{"POSITION", b.addFloats(positions, "VEC3")},
                      {"NORMAL", b.addFloats(normals, "VEC3")},
                      {"TEXCOORD_0", b.addFloats(uv0, "VEC2")}}},
                    {"indices", b.addIndices({0, 1, 2, 0, 2, 3})},
                    {"material", b.addMaterial(material)}};
  if (uv1) primitive["attributes"]["TEXCOORD_1"] = b.addFloats(uv1s, "VEC2");
  if (color == "VEC3") primitive["attributes"]["COLOR_0"] = b.addFloats(colors, "VEC3");
  if (color == "VEC4") {
    b.doc["accessors"].push_back({{"bufferView", b.addView(bytes.data(), bytes.size())},
                                  {"componentType", 5121},
                                  {"normalized", true},
                                  {"count", 4},
                                  {"type", "VEC4"}});
    primitive["attributes"]["COLOR_0"] = b.doc["accessors"].size() - 1;
  }
  b.addRootNode({{"mesh", b.addMesh(primitive)}});
  return b.writeGltf(dir.path(), name);
}

pbr::Scene squareScene(const std::string& path) {
  pbr::Scene scene;
  scene.camera.position = {0.0f, 0.0f, kDistance};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.fovYDeg = kFovY;
  scene.camera.nearPlane = 0.1f;
  scene.camera.farPlane = 10.0f;
  pbr::appendGltf(scene, path);
  return scene;
}

// Where pixel (x, y)'s centre sees the plane z = 0 from the head-on camera (images' row 0 is the top).
glm::vec2 worldAt(int x, int y) {
  const float halfHeight = kDistance * std::tan(glm::radians(kFovY / 2.0f));
  const glm::vec2 ndc((x + 0.5f) / kSize.x * 2.0f - 1.0f, 1.0f - (y + 0.5f) / kSize.y * 2.0f);
  return {ndc.x * halfHeight * kSize.x / kSize.y, ndc.y * halfHeight};
}

// The pixel whose centre sees world point p of the plane (rounded to the nearest).
glm::ivec2 pixelAt(glm::vec2 p) {
  const float halfHeight = kDistance * std::tan(glm::radians(kFovY / 2.0f));
  const glm::vec2 ndc(p.x / (halfHeight * kSize.x / kSize.y), p.y / halfHeight);
  return {int((ndc.x * 0.5f + 0.5f) * kSize.x), int((0.5f - ndc.y * 0.5f) * kSize.y)};
}

glm::vec3 rgb(const pbr::ImageRgbaF& image, glm::ivec2 p) {
  const float* v = image.at(p.x, p.y);
  return {v[0], v[1], v[2]};
}

}  // namespace

TEST_CASE("vertex colours: COLOR_0 as float RGB and normalized byte RGBA multiplies the base colour per pixel") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  const glm::vec3 base(0.8f, 0.9f, 0.7f);
  // Unlit, the pixel's radiance is base x colour, which the test interpolates itself.
  const json unlit = {{"pbrMetallicRoughness", {{"baseColorFactor", {base.x, base.y, base.z, 1.0}}}},
                      {"extensions", {{"KHR_materials_unlit", json::object()}}}};
  for (const std::string format : {"VEC3", "VEC4"}) {
    CAPTURE(format);
    const pbr::Scene scene = squareScene(square(dir, "colors_" + format, unlit, format, false));
    REQUIRE(scene.meshes.size() == 1);
    CHECK(scene.meshes[0].colors.size() == 4);
    const pbr::test::RenderedFrame frame = pbr::test::renderScene(scene, kSize, pbr::FrameOptions{});
    // Bytes round each corner by up to half a step; the field stays within that of the interpolated one.
    const float tolerance = format == "VEC4" ? 0.6f / 255.0f + 2e-3f : 2e-3f;
    int checked = 0;
    for (int y = 0; y < kSize.y; ++y) {
      for (int x = 0; x < kSize.x; ++x) {
        const glm::vec2 p = worldAt(x, y);
        if (std::abs(p.x) > 0.97f || std::abs(p.y) > 0.97f) continue;  // off the square or on its edge
        const glm::vec3 expected = base * field(p), got = rgb(frame.hdr, {x, y});
        for (int k = 0; k < 3; ++k) {
          if (std::abs(got[k] - expected[k]) > tolerance) {
            CAPTURE(x);
            CAPTURE(y);
            CHECK(got[k] == doctest::Approx(expected[k]));
          }
        }
        ++checked;
      }
    }
    MESSAGE(checked << " pixels checked");
    CHECK(checked > 1000);
  }
  // Lit, a uniform vertex colour equals that colour folded into the base colour factor.
  const json lit = {{"pbrMetallicRoughness", {{"baseColorFactor", {base.x, base.y, base.z, 1.0}}}}};
  pbr::Scene coloured = squareScene(square(dir, "lit_colors", lit, "VEC3", false));
  coloured.meshes[0].colors.assign(4, glm::vec4(0.5f, 0.25f, 1.0f, 1.0f));
  pbr::Scene folded = squareScene(square(dir, "lit_plain", lit, "", false));
  folded.objects[0].material.baseColor *= glm::vec3(0.5f, 0.25f, 1.0f);
  for (pbr::Scene* s : {&coloured, &folded}) {
    s->lights.push_back({{0.5f, 0.5f, 2.0f}, 10.0f, glm::vec3(1.0f), 300.0f});
    s->ambient = glm::vec3(0.05f);
  }
  const pbr::test::RenderedFrame a = pbr::test::renderScene(coloured, kSize, pbr::FrameOptions{});
  const pbr::test::RenderedFrame b = pbr::test::renderScene(folded, kSize, pbr::FrameOptions{});
  CHECK(rgb(a.hdr, pixelAt({0.0f, 0.0f})).x > 0.01f);
  CHECK(pbr::test::maxRelativeDifference(a.hdr, b.hdr, 1e-2) < 1e-2);
  // Meshes without colours keep their permutation: no stream, no define.
  for (const pbr::ShaderDefine& d : pbr::GBufferPass::streamPermutation(folded.meshes[0])) CHECK(d.value == "0");
  CHECK(folded.meshes[0].colors.empty());
}

TEST_CASE("vertex streams: a base colour map and an occlusion map on TEXCOORD_1 land where UV set 1 says") {
  PBR_REQUIRE_GL();
  const TempDir dir;
  // Left half of the image red (white for occlusion), right half green (black): through the mirrored second set,
  // the square's left shows the image's right.
  pbr::ImageRgba8 halves{2, 1, {255, 0, 0, 255, 0, 255, 0, 255}};
  pbr::ImageRgba8 shade{2, 1, {255, 255, 255, 255, 0, 0, 0, 255}};
  const json unlit = {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}},
                      {"extensions", {{"KHR_materials_unlit", json::object()}}}};
  const pbr::Scene colour = squareScene(square(dir, "uv1_color", unlit, "", true, {{"halves.png", halves}}));
  REQUIRE(colour.meshes[0].uv1.size() == 4);
  const pbr::test::RenderedFrame c = pbr::test::renderScene(colour, kSize, pbr::FrameOptions{});
  const glm::vec3 left = rgb(c.hdr, pixelAt({-0.5f, 0.0f})), right = rgb(c.hdr, pixelAt({0.5f, 0.0f}));
  CHECK(left.y == doctest::Approx(1.0f).epsilon(1e-3));
  CHECK(left.x == doctest::Approx(0.0f));
  CHECK(right.x == doctest::Approx(1.0f).epsilon(1e-3));
  CHECK(right.y == doctest::Approx(0.0f));
  // Occlusion darkens the ambient light only: with ambient light alone, the occluded half is black.
  const json occluded = {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
                         {"occlusionTexture", {{"index", 0}, {"texCoord", 1}}}};
  pbr::Scene ambient = squareScene(square(dir, "uv1_occlusion", occluded, "", true, {{"shade.png", shade}}));
  ambient.ambient = glm::vec3(0.5f);
  const pbr::test::RenderedFrame o = pbr::test::renderScene(ambient, kSize, pbr::FrameOptions{});
  const glm::vec3 dark = rgb(o.hdr, pixelAt({-0.5f, 0.0f})), bright = rgb(o.hdr, pixelAt({0.5f, 0.0f}));
  MESSAGE("occluded " << dark.x << ", open " << bright.x);
  CHECK(dark.x == doctest::Approx(0.0f));
  CHECK(bright.x > 0.05f);
  // A model whose maps all read TEXCOORD_0 carries no second set.
  const json plain = {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}};
  const pbr::Scene first = squareScene(square(dir, "uv0_color", plain, "", true, {{"halves0.png", halves}}));
  CHECK(first.meshes[0].uv1.empty());
}
