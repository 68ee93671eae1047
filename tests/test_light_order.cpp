#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>

#include "core/scene/builtin_scenes.hpp"
#include "core/scene/random.hpp"
#include "lighting/light_order.hpp"

using namespace pbr;

namespace {

bool isPermutation(std::vector<uint32_t> order, size_t n) {
  std::sort(order.begin(), order.end());
  std::vector<uint32_t> identity(n);
  std::iota(identity.begin(), identity.end(), 0u);
  return order == identity;
}

// The Z-order index of a point of a 4 x 4 x 4 grid, its coordinates' two bits interleaved x, y, z from the lowest.
uint32_t gridMorton(int x, int y, int z) {
  uint32_t code = 0;
  for (int bit = 0; bit < 2; ++bit) {
    code |= uint32_t((x >> bit) & 1) << (3 * bit) | uint32_t((y >> bit) & 1) << (3 * bit + 1) |
            uint32_t((z >> bit) & 1) << (3 * bit + 2);
  }
  return code;
}

PointLight lightAt(glm::vec3 position, glm::vec3 color = glm::vec3(1.0f)) {
  PointLight l;
  l.position = position;
  l.color = color;
  return l;
}

}  // namespace

TEST_CASE("light order: the buffer holds a 4x4x4 grid of lights in Z order, whatever the scene's order") {
  std::vector<PointLight> lights;
  for (int z = 3; z >= 0; --z) {
    for (int x = 0; x < 4; ++x) {
      for (int y = 3; y >= 0; --y) lights.push_back(lightAt(glm::vec3(x, y, z) * 2.5f + glm::vec3(-4.0f, 1.0f, 7.0f)));
    }
  }
  const std::vector<uint32_t> order = lightBufferOrder(lights);
  REQUIRE(isPermutation(order, lights.size()));
  for (size_t i = 0; i < order.size(); ++i) {
    const glm::vec3 cell = (lights[order[i]].position - glm::vec3(-4.0f, 1.0f, 7.0f)) / 2.5f;
    CAPTURE(i);
    CHECK(gridMorton(int(cell.x + 0.5f), int(cell.y + 0.5f), int(cell.z + 0.5f)) == i);
  }
}

TEST_CASE("light order: shuffling a scene's lights leaves the buffer's sequence of lights unchanged") {
  RandomLightSpec spec;
  spec.count = 3000;
  spec.seed = 5;
  spec.boundsMin = {-50.0f, 0.0f, -50.0f};
  spec.boundsMax = {50.0f, 2.0f, 50.0f};
  spec.spotShare = 0.3f;
  std::vector<PointLight> lights = makeRandomLights(spec);
  // Lights sharing a position (so a cell): an exact duplicate, and one of another colour.
  lights.push_back(lights[10]);
  lights.push_back(lightAt(lights[20].position, glm::vec3(0.2f, 0.4f, 0.9f)));
  lights.push_back(lightAt(lights[20].position, glm::vec3(0.9f, 0.4f, 0.2f)));
  const std::vector<uint32_t> order = lightBufferOrder(lights);
  REQUIRE(isPermutation(order, lights.size()));

  std::vector<PointLight> shuffled = lights;
  Pcg32 rng(77);
  for (size_t i = shuffled.size() - 1; i > 0; --i) std::swap(shuffled[i], shuffled[rng.next() % (i + 1)]);
  const std::vector<uint32_t> shuffledOrder = lightBufferOrder(shuffled);
  REQUIRE(isPermutation(shuffledOrder, shuffled.size()));
  size_t differing = 0;
  for (size_t i = 0; i < order.size(); ++i) {
    const PointLight &a = lights[order[i]], &b = shuffled[shuffledOrder[i]];
    const bool same = a.position == b.position && a.radius == b.radius && a.color == b.color &&
                      a.luminousPower == b.luminousPower && a.spot.has_value() == b.spot.has_value() &&
                      (!a.spot || (a.spot->direction == b.spot->direction && a.spot->innerAngle == b.spot->innerAngle &&
                                   a.spot->outerAngle == b.spot->outerAngle));
    differing += same ? 0 : 1;
  }
  CHECK(differing == 0);
}

TEST_CASE("light order: no lights, one light, and lights all at one point") {
  CHECK(lightBufferOrder({}).empty());
  CHECK(lightBufferOrder({lightAt(glm::vec3(1e30f, -1e30f, 0.0f))}) == std::vector<uint32_t>{0});
  // No extent to quantise: ordered by what the GPU receives, here their colour's red.
  const std::vector<PointLight> stacked = {lightAt(glm::vec3(2.0f), glm::vec3(0.3f)),
                                           lightAt(glm::vec3(2.0f), glm::vec3(0.1f)),
                                           lightAt(glm::vec3(2.0f), glm::vec3(0.2f))};
  CHECK(lightBufferOrder(stacked) == std::vector<uint32_t>{1, 2, 0});
  // The widest float extent still quantises without overflow.
  const std::vector<PointLight> far = {lightAt(glm::vec3(3e38f)), lightAt(glm::vec3(-3e38f)), lightAt(glm::vec3(0.0f))};
  CHECK(lightBufferOrder(far) == std::vector<uint32_t>{1, 2, 0});
}
