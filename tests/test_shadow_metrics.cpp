// The shadow rows' lit/shadowed metric (app/accuracy/shadow_metrics.hpp) on images whose answer is counted by hand,
// and the --shadow-rows list.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "app/accuracy/shadow_metrics.hpp"
#include "app/accuracy/shadow_rows.hpp"

namespace {

// A reference frame of one object filling w x h pixels, with the given per-pixel visibility.
pbr::reference::ReferenceFrame referenceWith(int w, int h, std::vector<float> visibility) {
  pbr::reference::ReferenceFrame f;
  f.radiance.width = w;
  f.radiance.height = h;
  f.radiance.pixels.assign(size_t(w) * h * 4, 0.0f);
  f.objectIds.assign(size_t(w) * h, 0);
  f.visibility = std::move(visibility);
  return f;
}

}  // namespace

TEST_CASE("shadow metrics: visibility is the shadowed frame over the unshadowed one, -1 where that is black") {
  pbr::ImageRgbaF shadowed{3, 1, {0.25f, 0.5f, 0.25f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.3f, 0.3f, 0.3f, 1.0f}};
  pbr::ImageRgbaF unshadowed{3, 1, {1.0f, 1.0f, 2.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.1f, 0.1f, 0.1f, 1.0f}};
  const std::vector<float> v = pbr::visibilityRatio(shadowed, unshadowed);
  REQUIRE(v.size() == 3);
  CHECK(v[0] == doctest::Approx(0.25));  // (0.25 + 0.5 + 0.25) / (1 + 1 + 2)
  CHECK(v[1] == -1.0f);
  CHECK(v[2] == doctest::Approx(3.0));  // brighter shadowed than not: counted lit, as any ratio >= 0.5
  unshadowed.width = 1;
  CHECK_THROWS_AS(pbr::visibilityRatio(shadowed, unshadowed), std::invalid_argument);
}

TEST_CASE("shadow metrics: misclassified pixels are counted outside the penumbra band and nowhere else") {
  // 12 x 8 pixels: the reference lit left of x = 6, shadowed from x = 6 on. A band of 2 pixels leaves out
  // x = 4, 5 (lit, within 2 of a shadowed pixel) and x = 6, 7: 4 lit and 4 shadowed columns are compared.
  constexpr int w = 12, h = 8;
  std::vector<float> expected(w * h), gpu(w * h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      expected[y * w + x] = x < 6 ? 1.0f : 0.0f;
      gpu[y * w + x] = x < 5 ? 1.0f : x == 5 ? 0.6f : 0.0f;  // a soft edge, a pixel early
    }
  }
  const pbr::reference::ReferenceFrame ref = referenceWith(w, h, expected);
  SUBCASE("a frame that agrees outside the band") {
    gpu[3 * w + 4] = 0.0f;  // wrong, but inside the band
    gpu[5 * w + 7] = 1.0f;  // wrong, inside the band
    const pbr::ShadowAgreement a = pbr::compareShadowState(gpu, ref, 2);
    CHECK(a.compared == 64);
    CHECK(a.shadowed == 32);
    CHECK(a.misclassified == 0);
    CHECK(a.misclassifiedShare() == 0.0);
  }
  SUBCASE("three wrong pixels and one the GPU frame cannot say") {
    gpu[1 * w + 1] = 0.2f;   // lit in the reference, shadowed here
    gpu[6 * w + 10] = 0.9f;  // shadowed in the reference, lit here
    gpu[2 * w + 9] = 0.5f;   // 0.5 is lit
    gpu[0] = -1.0f;          // black unshadowed frame: not compared
    const pbr::ShadowAgreement a = pbr::compareShadowState(gpu, ref, 2);
    CHECK(a.compared == 63);
    CHECK(a.shadowed == 32);
    CHECK(a.misclassified == 3);
    CHECK(a.misclassifiedShare() == doctest::Approx(3.0 / 63.0));
    pbr::ShadowAgreement sum = a;
    sum += a;
    CHECK(sum.compared == 126);
    CHECK(sum.misclassified == 6);
    CHECK(sum.misclassifiedShare() == doctest::Approx(3.0 / 63.0));
  }
  SUBCASE("a wider band compares fewer pixels") {
    const pbr::ShadowAgreement a = pbr::compareShadowState(gpu, ref, 3);
    CHECK(a.compared == 48);  // x = 0..2 and 9..11
  }
}

TEST_CASE("shadow metrics: pixels the light does not reach, background and silhouettes are not compared") {
  // 8 x 8: the light reaches the right half only (-1 on the left); the GPU frame says lit everywhere.
  constexpr int w = 8, h = 8;
  std::vector<float> expected(w * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) expected[y * w + x] = x < 4 ? -1.0f : 1.0f;
  const std::vector<float> gpu(w * h, 1.0f);
  pbr::reference::ReferenceFrame ref = referenceWith(w, h, expected);
  // x = 4, 5 lie within 2 pixels of the unreached half: only x = 6, 7 are compared.
  CHECK(pbr::compareShadowState(gpu, ref, 2).compared == 16);
  // Row 0 is background, so rows 0 and 1 (a silhouette's neighbours) drop out too.
  for (int x = 0; x < w; ++x) ref.objectIds[x] = -1;
  const pbr::ShadowAgreement a = pbr::compareShadowState(gpu, ref, 2);
  CHECK(a.compared == 12);
  CHECK(a.misclassified == 0);
  CHECK_THROWS_AS(pbr::compareShadowState(std::vector<float>(3, 1.0f), ref, 2), std::invalid_argument);
}

TEST_CASE("shadow rows: the default list, names, and refused items") {
  const std::vector<pbr::ShadowRow> rows = pbr::parseShadowRows(pbr::kDefaultShadowRows);
  std::vector<std::string> names;
  for (const pbr::ShadowRow& r : rows) names.push_back(r.name);
  CHECK(names == std::vector<std::string>{"unshadowed", "shadow-hard-4096", "shadow-pcf3x3-4096",
                                          "shadow-poisson16-4096", "shadow-pcf3x3-1024", "shadow-pcf3x3-16384"});
  REQUIRE(rows.size() == 6);
  CHECK((rows[0].settings.mode == pbr::ShadowMode::None));
  CHECK((rows[1].settings.mode == pbr::ShadowMode::Auto));
  CHECK((rows[1].settings.filter == pbr::ShadowFilter::Hard));
  CHECK((rows[5].settings.filter == pbr::ShadowFilter::Pcf3x3));
  CHECK(rows[5].settings.atlasSize == 16384);
  CHECK(pbr::parseShadowRows("none").empty());
  CHECK(pbr::parseShadowRows("poisson16:256").at(0).settings.atlasSize == 256);
  for (const char* bad : {"pcf3x3:1000", "pcf3x3:128", "pcf3x3:32768", "pcf5x5", "pcf3x3:4k", "pcf3x3:", "", ","}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(pbr::parseShadowRows(bad), std::invalid_argument);
  }
}
