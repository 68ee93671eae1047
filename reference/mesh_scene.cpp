#include "reference/mesh_scene.hpp"

#include <string>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace pbr::reference {

MeshScene::MeshScene(const Scene& scene) {
  std::vector<Aabb> boxes;
  Aabb bounds;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (o.mesh < 0 || size_t(o.mesh) >= scene.meshes.size()) {
      throw SceneError(scene.name + ": objects[" + std::to_string(i) + "].mesh: no mesh " + std::to_string(o.mesh) +
                       " in a scene of " + std::to_string(scene.meshes.size()));
    }
    const MeshData& mesh = scene.meshes[size_t(o.mesh)];
    const glm::dmat4 model(o.transform);
    // The G-buffer pass's normal matrix: the inverse transpose of the model matrix, whose upper 3x3 it applies.
    const glm::dmat3 normalMatrix(glm::transpose(glm::inverse(model)));
    Object object;
    object.indices = &mesh.indices;
    object.frontSign = glm::determinant(glm::dmat3(model)) < 0.0 ? -1.0 : 1.0;
    object.doubleSided = o.material.doubleSided;
    object.stopsShadowRays = stopsShadowRays(o.material);
    for (const Vertex& v : mesh.vertices) {
      object.positions.push_back(dvec3(model * glm::dvec4(dvec3(v.position), 1.0)));
      object.normals.push_back(normalMatrix * dvec3(v.normal));
    }
    for (size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
      Aabb box;
      for (size_t c = 0; c < 3; ++c) box.grow(object.positions.at(mesh.indices[k + c]));
      boxes.push_back(box);
      bounds.grow(box);
      triangles_.push_back({uint32_t(i), uint32_t(k)});
    }
    objects_.push_back(std::move(object));
  }
  bvh_ = Bvh(boxes);
  extent_ = bounds.diagonal();
}

// Möller & Trumbore 1997, "Fast, minimum storage ray-triangle intersection".
std::optional<MeshScene::Crossing> MeshScene::cross(const Triangle& triangle, const Ray& ray, double tMin,
                                                    double tMax, bool bothFaces) const {
  const Object& o = objects_[triangle.object];
  const uint32_t* index = &(*o.indices)[triangle.firstIndex];
  const dvec3& p0 = o.positions[index[0]];
  const dvec3 e1 = o.positions[index[1]] - p0, e2 = o.positions[index[2]] - p0;
  const dvec3 p = glm::cross(ray.direction, e2);
  // det = -dot(direction, cross(e1, e2)): positive where the ray meets the counter-clockwise (front) side.
  const double det = glm::dot(e1, p);
  const bool front = det * o.frontSign > 0.0;
  if (det == 0.0 || (!front && !bothFaces)) return std::nullopt;
  const dvec3 s = ray.origin - p0;
  const double u = glm::dot(s, p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(ray.direction, q) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = glm::dot(e2, q) / det;
  if (t < tMin || t > tMax) return std::nullopt;
  return Crossing{t, u, v, front};
}

std::optional<Hit> MeshScene::hitTriangle(const Triangle& triangle, const Ray& ray, double tMin, double tMax) const {
  const Object& o = objects_[triangle.object];
  const std::optional<Crossing> c = cross(triangle, ray, tMin, tMax, o.doubleSided);
  if (!c) return std::nullopt;
  const uint32_t* index = &(*o.indices)[triangle.firstIndex];
  dvec3 n = glm::normalize((1.0 - c->u - c->v) * o.normals[index[0]] + c->u * o.normals[index[1]] +
                           c->v * o.normals[index[2]]);
  if (!c->front) n = -n;  // a double-sided surface seen from behind faces the other way
  return Hit{c->t, ray.origin + c->t * ray.direction, n, triangle.object};
}

std::optional<Hit> MeshScene::closestHit(const Ray& ray, double tMin, double tMax) const {
  std::optional<Hit> best;
  bvh_.traverse(ray, tMin, tMax, [&](uint32_t i, double tFar) {
    const std::optional<Hit> hit = hitTriangle(triangles_[i], ray, tMin, tFar);
    if (!hit) return tFar;
    best = hit;
    return hit->t;
  });
  return best;
}

std::optional<Hit> MeshScene::exitHit(const Ray& ray, double tMin, double tMax, size_t object) const {
  std::optional<Hit> best;
  bvh_.traverse(ray, tMin, tMax, [&](uint32_t i, double tFar) {
    const Triangle& triangle = triangles_[i];
    if (triangle.object != object) return tFar;
    const std::optional<Crossing> c = cross(triangle, ray, tMin, tFar, true);
    if (!c || c->front) return tFar;
    const Object& o = objects_[triangle.object];
    const uint32_t* index = &(*o.indices)[triangle.firstIndex];
    const dvec3 n = glm::normalize((1.0 - c->u - c->v) * o.normals[index[0]] + c->u * o.normals[index[1]] +
                                   c->v * o.normals[index[2]]);
    best = Hit{c->t, ray.origin + c->t * ray.direction, n, triangle.object};
    return c->t;
  });
  return best;
}

bool MeshScene::occluded(const Ray& ray, double tMin, double tMax) const {
  return bvh_.any(ray, tMin, tMax, [&](uint32_t i) {
    const Triangle& triangle = triangles_[i];
    return objects_[triangle.object].stopsShadowRays && cross(triangle, ray, tMin, tMax, true).has_value();
  });
}

}  // namespace pbr::reference
