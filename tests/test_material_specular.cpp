// KHR_materials_ior and KHR_materials_specular on the GPU: against the CPU reference, which evaluates them from
// the specifications' formulas on its own (reference/reference_brdf.cpp), and the core material unchanged in a
// scene whose G-buffer carries the dielectric's F0 and F90.
#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "gbuffer/gbuffer.hpp"
#include "reference/reference_renderer.hpp"
#include "renderer/offscreen.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/render_util.hpp"

namespace {

const glm::ivec2 kSize{192, 192};

pbr::Material dielectric(float ior, float specular, glm::vec3 color) {
  pbr::Material m;
  m.baseColor = {0.2f, 0.3f, 0.8f};
  m.roughness = 0.3f;
  m.ior = ior;
  m.specular = specular;
  m.specularColor = color;
  return m;
}

// A 3x3 grid of spheres: the core material, then ior 1 (no reflection at normal incidence), 2.4 (diamond), 0 (F0
// 1, the specular-glossiness conversion's), specular 0 and 0.5, a red and an over-1 specular colour, and a tinted
// ior 1.33; two point lights and `ambient`.
pbr::Scene grid(float ambient) {
  const pbr::Material materials[] = {
      dielectric(1.5f, 1.0f, glm::vec3(1.0f)),        dielectric(1.0f, 1.0f, glm::vec3(1.0f)),
      dielectric(2.4f, 1.0f, glm::vec3(1.0f)),        dielectric(0.0f, 1.0f, glm::vec3(1.0f)),
      dielectric(1.5f, 0.0f, glm::vec3(1.0f)),        dielectric(1.5f, 0.5f, glm::vec3(1.0f)),
      dielectric(1.5f, 1.0f, {1.0f, 0.2f, 0.2f}),     dielectric(1.5f, 1.0f, glm::vec3(3.0f)),
      dielectric(1.33f, 1.0f, {0.2f, 1.0f, 0.4f})};
  pbr::Scene scene;
  scene.camera.position = {0.0f, 0.0f, 10.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.ambient = glm::vec3(ambient);
  for (int i = 0; i < 9; ++i) {
    const glm::vec3 at{float(i % 3 - 1) * 2.4f, float(1 - i / 3) * 2.4f, 0.0f};
    scene.addShape(pbr::Shape::Sphere, glm::translate(glm::mat4(1.0f), at), materials[i]);
  }
  scene.lights.push_back({{-4.0f, 4.0f, 5.0f}, 30.0f, glm::vec3(1.0f), 500.0f});
  scene.lights.push_back({{4.0f, -4.0f, 5.0f}, 30.0f, glm::vec3(1.0f), 500.0f});
  return scene;
}

// Float G-buffer and radiance target: what remains against the reference is float arithmetic and the forms.
pbr::RenderedFrames renderFloat(const pbr::Scene& scene, const pbr::ShadingVariant& variant) {
  pbr::RendererConfig config;
  config.hdrFormat = pbr::HdrFormat::Rgba32f;
  config.gbuffer = pbr::GBufferPrecision::Float;
  pbr::FrameOptions options;
  options.variant = variant;
  const pbr::ShaderLibrary shaders;
  return pbr::renderOffscreen(shaders, scene, kSize, options, 2, config);
}

// Pixels of `a` and `b` whose radiance differs in any colour channel, in the frame's left and right halves.
std::pair<int, int> differingHalves(const pbr::RenderedFrames& a, const pbr::RenderedFrames& b) {
  int left = 0, right = 0;
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) {
      const size_t i = 4 * (size_t(y) * kSize.x + x);
      const bool same = a.hdr.pixels[i] == b.hdr.pixels[i] && a.hdr.pixels[i + 1] == b.hdr.pixels[i + 1] &&
                        a.hdr.pixels[i + 2] == b.hdr.pixels[i + 2];
      (x < kSize.x / 2 ? left : right) += same ? 0 : 1;
    }
  }
  return {left, right};
}

// Relative RMSE of the GPU frame of `scene` against the reference's, both with the Fresnel form `fresnel`.
double referenceError(const pbr::Scene& scene, const char* fresnel) {
  const pbr::ShadingVariant variant = pbr::parseShadingVariant(std::string("fresnel=") + fresnel);
  pbr::reference::ReferenceOptions options;
  options.forms = pbr::reference::BrdfForms(variant);
  const pbr::reference::ReferenceFrame ref = pbr::reference::renderReference(scene, kSize.x, kSize.y, options);
  return pbr::test::relativeRmse(renderFloat(scene, variant).hdr, ref.radiance);
}

}  // namespace

TEST_CASE("material specular: ior, specular strength and colour match the CPU reference, direct light alone") {
  PBR_REQUIRE_GL();
  // The reference's forms: exact Fresnel, each channel's index of refraction taken from F0 / F90.
  const double error = referenceError(grid(0.0f), "exact");
  MESSAGE("relative RMSE " << error);
  CHECK(error < 1e-4);  // 1e-5 measured on llvmpipe
}

TEST_CASE("material specular: with uniform ambient light, Schlick's forms on both sides match the reference") {
  PBR_REQUIRE_GL();
  // The ambient term takes a dielectric's albedo from Schlick's split F0 A + F90 B of the variant's table, which
  // is exact for Schlick's form: the default model's, within its budget of 1e-3.
  const double error = referenceError(grid(0.02f), "schlick");
  MESSAGE("relative RMSE " << error);
  CHECK(error < 1e-3);  // 2e-4 measured on llvmpipe
}

TEST_CASE("material specular: the core material renders bit for bit where the G-buffer carries F0 and F90") {
  PBR_REQUIRE_GL();
  // Two core spheres, then the right one given specular 0.5: the scene's G-buffer gains the specular channel and
  // its programs the MATERIAL_SPECULAR permutation, and the left sphere's pixels stay exactly what they were.
  pbr::Scene plain;
  plain.camera.position = {0.0f, 0.0f, 8.0f};
  plain.camera.target = {0.0f, 0.0f, 0.0f};
  plain.ambient = glm::vec3(0.03f);
  pbr::Material core = dielectric(1.5f, 1.0f, glm::vec3(1.0f));
  core.metalness = 0.4f;  // both parts of the Fresnel mix
  plain.addShape(pbr::Shape::Sphere, glm::translate(glm::mat4(1.0f), {-1.6f, 0.0f, 0.0f}), core);
  plain.addShape(pbr::Shape::Sphere, glm::translate(glm::mat4(1.0f), {1.6f, 0.0f, 0.0f}), core);
  plain.lights.push_back({{-3.0f, 3.0f, 4.0f}, 30.0f, glm::vec3(1.0f), 400.0f});
  pbr::Scene extended = plain;
  extended.objects[1].material.specular = 0.5f;
  REQUIRE_FALSE(pbr::gbufferLayout(plain).specular);
  REQUIRE(pbr::gbufferLayout(extended).specular);
  for (const char* variant : {"", "fresnel=exact", "fresnel=schlick-sg,diffuse=lambert-1-f-vh"}) {
    CAPTURE(variant);
    pbr::FrameOptions options;
    options.variant = pbr::parseShadingVariant(variant);
    const pbr::test::RenderedFrame a = pbr::test::renderScene(plain, kSize, options);
    const pbr::test::RenderedFrame b = pbr::test::renderScene(extended, kSize, options);
    const auto [differentLeft, differentRight] = differingHalves(a, b);
    CHECK(differentLeft == 0);
    CHECK(differentRight > 100);  // the half-strength sphere does change
  }
}

TEST_CASE("material specular: the G-buffer gains 8 bytes a pixel only for a scene whose materials need them") {
  PBR_REQUIRE_GL();
  const pbr::Texture radiance("test.radiance", GL_RGBA16F, 10, 10);
  const pbr::GBuffer lean(10, 10, radiance);
  CHECK(lean.bytes() == 100 * 16);
  CHECK_FALSE(lean.specular.has_value());
  const pbr::GBuffer specular(10, 10, radiance, pbr::GBufferPrecision::Lean, {true});
  CHECK(specular.bytes() == 100 * 24);
  REQUIRE(specular.specular.has_value());
  CHECK(specular.specular->format() == GL_RGBA16F);
  CHECK(pbr::GBuffer(10, 10, radiance, pbr::GBufferPrecision::Float, {true}).bytes() == 100 * (44 + 16));
  CHECK(pbr::GBufferLayout{true}.describe(pbr::GBufferPrecision::Lean) ==
        "lean + specular, 24 bytes per pixel (base colour, normal, material, depth, dielectric F0 and F90)");
  // ior 1.5, specular 1 and a white colour are the core material: no channel for them.
  pbr::Scene scene = grid(0.0f);
  scene.objects.resize(1);
  CHECK_FALSE(pbr::gbufferLayout(scene).specular);
}

namespace {

pbr::Material coated(float clearcoat, float roughness, float metalness = 0.0f) {
  pbr::Material m = dielectric(1.5f, 1.0f, glm::vec3(1.0f));
  m.roughness = 0.5f;
  m.metalness = metalness;
  m.clearcoat = clearcoat;
  m.clearcoatRoughness = roughness;
  return m;
}

// Clear coats of strength 1, 0.5 and 0.2, rough and smooth, over dielectric and metal bases, and none.
pbr::Scene coatGrid(float ambient) {
  pbr::Scene scene = grid(ambient);
  const pbr::Material materials[] = {coated(1.0f, 0.0f),       coated(1.0f, 0.3f), coated(0.5f, 0.1f),
                                     coated(1.0f, 0.05f, 1.0f), coated(0.0f, 0.0f), coated(1.0f, 1.0f),
                                     coated(0.2f, 0.6f),        coated(1.0f, 0.6f), coated(0.7f, 0.2f, 0.5f)};
  for (size_t i = 0; i < scene.objects.size(); ++i) scene.objects[i].material = materials[i];
  return scene;
}

}  // namespace

TEST_CASE("material clearcoat: the coat over dielectric and metal bases matches the CPU reference") {
  PBR_REQUIRE_GL();
  // Direct light with the reference's forms, then uniform ambient light with Schlick's on both sides (the ambient
  // table's split is Schlick's); smooth coats' sharp highlights leave 4e-4 of float arithmetic (llvmpipe).
  {
    const double error = referenceError(coatGrid(0.0f), "exact");
    MESSAGE("direct: relative RMSE " << error);
    CHECK(error < 1e-3);
  }
  {
    const double error = referenceError(coatGrid(0.02f), "schlick");
    MESSAGE("with ambient: relative RMSE " << error);
    CHECK(error < 1e-3);
  }
}

TEST_CASE("material clearcoat: a coat of strength 0 renders the base model bit for bit") {
  PBR_REQUIRE_GL();
  pbr::Scene plain;
  plain.camera.position = {0.0f, 0.0f, 8.0f};
  plain.camera.target = {0.0f, 0.0f, 0.0f};
  plain.ambient = glm::vec3(0.03f);
  pbr::Material core = coated(0.0f, 0.0f, 0.4f);
  core.emissive = glm::vec3(0.05f, 0.0f, 0.0f);  // the coat darkens emission: not where it is 0
  plain.addShape(pbr::Shape::Sphere, glm::translate(glm::mat4(1.0f), {-1.6f, 0.0f, 0.0f}), core);
  plain.addShape(pbr::Shape::Sphere, glm::translate(glm::mat4(1.0f), {1.6f, 0.0f, 0.0f}), core);
  plain.lights.push_back({{-3.0f, 3.0f, 4.0f}, 30.0f, glm::vec3(1.0f), 400.0f});
  pbr::Scene extended = plain;
  extended.objects[1].material.clearcoat = 1.0f;
  REQUIRE(pbr::gbufferLayout(extended).clearcoat);
  const pbr::test::RenderedFrame a = pbr::test::renderScene(plain, kSize, {});
  const pbr::test::RenderedFrame b = pbr::test::renderScene(extended, kSize, {});
  const auto [differentLeft, differentRight] = differingHalves(a, b);
  CHECK(differentLeft == 0);
  CHECK(differentRight > 100);
}

namespace {

pbr::Material sheened(glm::vec3 color, float roughness, float metalness = 0.0f) {
  pbr::Material m = coated(0.0f, 0.0f, metalness);
  m.sheenColor = color;
  m.sheenRoughness = roughness;
  return m;
}

// White, red, blue and dark sheens, rough and sharp, over dielectric and metal bases, one under a clear coat, none.
pbr::Scene sheenGrid(float ambient) {
  pbr::Scene scene = grid(ambient);
  pbr::Material underCoat = sheened({0.3f, 1.0f, 0.3f}, 0.5f);
  underCoat.clearcoat = 1.0f;
  underCoat.clearcoatRoughness = 0.2f;
  const pbr::Material materials[] = {sheened(glm::vec3(1.0f), 0.3f),      sheened({1.0f, 0.2f, 0.2f}, 0.8f),
                                     sheened({0.5f, 0.5f, 1.0f}, 0.07f),   sheened(glm::vec3(1.0f), 1.0f),
                                     sheened(glm::vec3(0.0f), 0.5f),       underCoat,
                                     sheened(glm::vec3(1.0f), 0.5f, 1.0f), sheened(glm::vec3(0.2f), 0.2f),
                                     sheened({1.0f, 1.0f, 0.0f}, 0.6f)};
  for (size_t i = 0; i < scene.objects.size(); ++i) scene.objects[i].material = materials[i];
  return scene;
}

}  // namespace

TEST_CASE("material sheen: the Charlie lobe and its albedo scaling match the CPU reference") {
  PBR_REQUIRE_GL();
  // The GPU's E table (sheen_albedo.comp, 1024 samples a texel) against the reference's own quadrature.
  {
    const double error = referenceError(sheenGrid(0.0f), "exact");
    MESSAGE("direct: relative RMSE " << error);
    CHECK(error < 1e-3);  // 4e-4 measured on llvmpipe
  }
  {
    const double error = referenceError(sheenGrid(0.02f), "schlick");
    MESSAGE("with ambient: relative RMSE " << error);
    CHECK(error < 1e-3);
  }
}

TEST_CASE("material sheen: a black sheen renders the base model bit for bit") {
  PBR_REQUIRE_GL();
  pbr::Scene plain;
  plain.camera.position = {0.0f, 0.0f, 8.0f};
  plain.camera.target = {0.0f, 0.0f, 0.0f};
  plain.ambient = glm::vec3(0.03f);
  const pbr::Material core = sheened(glm::vec3(0.0f), 0.5f, 0.4f);
  plain.addShape(pbr::Shape::Sphere, glm::translate(glm::mat4(1.0f), {-1.6f, 0.0f, 0.0f}), core);
  plain.addShape(pbr::Shape::Sphere, glm::translate(glm::mat4(1.0f), {1.6f, 0.0f, 0.0f}), core);
  plain.lights.push_back({{-3.0f, 3.0f, 4.0f}, 30.0f, glm::vec3(1.0f), 400.0f});
  pbr::Scene extended = plain;
  extended.objects[1].material.sheenColor = glm::vec3(1.0f);
  REQUIRE(pbr::gbufferLayout(extended).sheen);
  for (const char* environment : {"none", "sky"}) {
    CAPTURE(environment);
    pbr::Scene a = plain, b = extended;
    if (std::string(environment) == "sky") {
      a.environment = b.environment = pbr::EnvironmentDesc{};  // the procedural sky
    }
    const pbr::test::RenderedFrame fa = pbr::test::renderScene(a, kSize, {});
    const pbr::test::RenderedFrame fb = pbr::test::renderScene(b, kSize, {});
    const auto [differentLeft, differentRight] = differingHalves(fa, fb);
    CHECK(differentLeft == 0);
    CHECK(differentRight > 100);
  }
}

TEST_CASE("material lobes: an extension's lobe switched off renders the scene without it, bit for bit") {
  PBR_REQUIRE_GL();
  // The viewer's switches (MaterialLobes): off, the lighting passes leave the lobe out, as for a scene whose
  // materials lack the extension, though the G-buffer keeps its channel.
  struct Case {
    const char* name;
    pbr::Scene scene;
    void (*strip)(pbr::Material&);
    void (*off)(pbr::MaterialLobes&);
  };
  const Case cases[] = {
      {"specular", grid(0.02f),
       [](pbr::Material& m) {
         m.ior = 1.5f;
         m.specular = 1.0f;
         m.specularColor = glm::vec3(1.0f);
       },
       [](pbr::MaterialLobes& l) { l.specular = false; }},
      {"clearcoat", coatGrid(0.02f), [](pbr::Material& m) { m.clearcoat = 0.0f; },
       [](pbr::MaterialLobes& l) { l.clearcoat = false; }},
      {"sheen", sheenGrid(0.02f), [](pbr::Material& m) { m.sheenColor = glm::vec3(0.0f); },
       [](pbr::MaterialLobes& l) { l.sheen = false; }},
  };
  for (const Case& c : cases) {
    CAPTURE(c.name);
    pbr::Scene without = c.scene;
    for (pbr::SceneObject& o : without.objects) c.strip(o.material);
    pbr::FrameOptions off;
    c.off(off.lobes);
    const pbr::test::RenderedFrame switched = pbr::test::renderScene(c.scene, kSize, off);
    const pbr::test::RenderedFrame stripped = pbr::test::renderScene(without, kSize, {});
    CHECK(switched.hdr.pixels == stripped.hdr.pixels);
    CHECK(pbr::test::renderScene(c.scene, kSize, {}).hdr.pixels != stripped.hdr.pixels);  // the lobe does show
  }
}

namespace {

// A 4x4 texture of one value in every channel (linear, or sRGB-encoded for the colour maps).
int uniformTexture(pbr::Scene& scene, uint8_t value, bool srgb) {
  pbr::TextureData t;
  t.name = "uniform";
  t.width = t.height = 4;
  t.rgba.assign(4 * 4 * 4, value);
  t.srgb = srgb;
  scene.textures.push_back(t);
  return int(scene.textures.size()) - 1;
}

// The linear value a texel of `value` reads as.
float texelValue(uint8_t value, bool srgb) {
  const float c = float(value) / 255.0f;
  return srgb ? (c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f)) : c;
}

}  // namespace

TEST_CASE("material maps: each extension's map multiplies its factor as the specification says") {
  PBR_REQUIRE_GL();
  // A scene with a map of one value v against the same scene with the factor times v and no map: the same frame
  // up to the texel's rounding (relative RMSE). Uniform maps leave the UVs and filtering out of it.
  const uint8_t v = 150;
  struct Case {
    const char* name;
    pbr::Scene scene;
    bool srgb;
    void (*map)(pbr::Material&, int texture);
    void (*scale)(pbr::Material&, float by);
  };
  const Case cases[] = {
      {"clearcoat", coatGrid(0.02f), false, [](pbr::Material& m, int t) { m.clearcoatMap.texture = t; },
       [](pbr::Material& m, float by) { m.clearcoat *= by; }},
      {"clearcoat roughness", coatGrid(0.02f), false,
       [](pbr::Material& m, int t) { m.clearcoatRoughnessMap.texture = t; },
       [](pbr::Material& m, float by) { m.clearcoatRoughness *= by; }},
      {"sheen colour", sheenGrid(0.02f), true, [](pbr::Material& m, int t) { m.sheenColorMap.texture = t; },
       [](pbr::Material& m, float by) { m.sheenColor *= by; }},
      {"sheen roughness", sheenGrid(0.02f), false, [](pbr::Material& m, int t) { m.sheenRoughnessMap.texture = t; },
       [](pbr::Material& m, float by) { m.sheenRoughness *= by; }},
      {"specular", grid(0.02f), false, [](pbr::Material& m, int t) { m.specularMap.texture = t; },
       [](pbr::Material& m, float by) { m.specular *= by; }},
      {"specular colour", grid(0.02f), true, [](pbr::Material& m, int t) { m.specularColorMap.texture = t; },
       [](pbr::Material& m, float by) { m.specularColor *= by; }},
  };
  for (const Case& c : cases) {
    CAPTURE(c.name);
    pbr::Scene mapped = c.scene, scaled = c.scene;
    const int texture = uniformTexture(mapped, v, c.srgb);
    for (pbr::SceneObject& o : mapped.objects) c.map(o.material, texture);
    for (pbr::SceneObject& o : scaled.objects) c.scale(o.material, texelValue(v, c.srgb));
    const double error =
        pbr::test::relativeRmse(renderFloat(mapped, {}).hdr, renderFloat(scaled, {}).hdr);
    MESSAGE(std::string(c.name) << ": relative RMSE " << error);
    CHECK(error < 2e-3);
    // And the map does change the frame.
    CHECK(pbr::test::relativeRmse(renderFloat(mapped, {}).hdr, renderFloat(c.scene, {}).hdr) > 1e-3);
  }
}
