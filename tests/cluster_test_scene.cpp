#include "tests/cluster_test_scene.hpp"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

namespace pbr::test {

Scene clusterScene() {
  Scene s;
  s.name = "cluster-test";
  s.camera.position = {0.0f, 2.0f, 6.0f};
  s.camera.target = {0.0f, 0.5f, 0.0f};
  s.camera.nearPlane = 0.3f;
  s.camera.farPlane = 40.0f;
  s.ambient = glm::vec3(0.01f);
  s.addShape(Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(60.0f, 1.0f, 60.0f)), {glm::vec3(0.6f), 0.7f, 0.0f});
  s.addShape(Shape::Box, glm::translate(glm::mat4(1.0f), glm::vec3(-1.5f, 0.5f, -1.0f)),
             {glm::vec3(0.8f, 0.3f, 0.2f), 0.3f, 0.0f});
  s.addShape(Shape::Sphere, glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1.2f, 0.8f, 0.5f)), glm::vec3(1.6f)),
             {glm::vec3(0.9f, 0.8f, 0.5f), 0.25f, 1.0f});
  return s;
}

Scene litClusterScene(int lights, uint64_t seed, float radiusMin, float radiusMax, float spotShare) {
  Scene s = clusterScene();
  RandomLightSpec spec;
  spec.count = lights;
  spec.seed = seed;
  spec.boundsMin = {-12.0f, 0.05f, -30.0f};
  spec.boundsMax = {12.0f, 4.0f, 8.0f};
  spec.radiusMin = radiusMin;
  spec.radiusMax = radiusMax;
  spec.powerMin = 40.0f / float(std::max(lights, 1));
  spec.powerMax = 400.0f / float(std::max(lights, 1));
  spec.spotShare = spotShare;
  s.lights = makeRandomLights(spec);
  return s;
}

}  // namespace pbr::test
