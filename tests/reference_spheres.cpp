#include "tests/reference_spheres.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace pbr::test {

namespace {

glm::mat4 placed(const glm::vec3& at, const glm::vec3& scale) {
  return glm::scale(glm::translate(glm::mat4(1.0f), at), scale);
}

}  // namespace

Scene sphereScene(const MeshData& mesh) {
  Scene s;
  s.name = "spheres";
  s.camera.position = {0.0f, 0.0f, 5.0f};
  s.camera.fovYDeg = 45.0f;
  s.camera.nearPlane = 0.5f;
  s.camera.farPlane = 20.0f;
  const int m =
      s.addShape(Shape::Sphere, placed({-1.1f, 0, 0}, glm::vec3(2.0f)), Material{{0.9f, 0.6f, 0.3f}, 0.4f, 0.0f}).mesh;
  s.meshes[size_t(m)] = mesh;
  s.addShape(Shape::Sphere, placed({1.1f, 0, 0}, {-2.0f, 2.0f, 2.0f}), Material{{0.95f, 0.64f, 0.54f}, 0.25f, 1.0f});
  s.lights = {{{2.0f, 2.0f, 3.0f}, 20.0f, glm::vec3(1.0f), 400.0f},
              {{-3.0f, -1.0f, 2.0f}, 20.0f, {1.0f, 0.9f, 0.8f}, 200.0f}};
  return s;
}

reference::ReferenceFrame renderWith(const Scene& scene, reference::Geometry geometry) {
  reference::ReferenceOptions options;
  options.geometry = geometry;
  return reference::renderReference(scene, kReferenceSize.x, kReferenceSize.y, options);
}

}  // namespace pbr::test
