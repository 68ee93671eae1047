#include "reference/raycast.hpp"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

namespace pbr::reference {

namespace {

// Object-space intersections; `n` receives the object-space outward normal.
std::optional<double> hitPlane(const dvec3& o, const dvec3& d, dvec3& n) {
  if (d.y >= 0.0 || o.y <= 0.0) return std::nullopt;  // front face (+Y) only
  const double t = -o.y / d.y;
  const dvec3 p = o + t * d;
  if (std::abs(p.x) > 0.5 || std::abs(p.z) > 0.5) return std::nullopt;
  n = dvec3(0, 1, 0);
  return t;
}

std::optional<double> hitSphere(const dvec3& o, const dvec3& d, dvec3& n) {
  const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - 0.25;
  const double disc = b * b - a * c;
  if (disc < 0.0) return std::nullopt;
  const double t = (-b - std::sqrt(disc)) / a;  // the entering root: front faces only
  if (t <= 0.0) return std::nullopt;
  n = glm::normalize(o + t * d);
  return t;
}

// Slab test (Kay & Kajiya 1986), entering face only.
std::optional<double> hitBox(const dvec3& o, const dvec3& d, dvec3& n) {
  double tNear = -std::numeric_limits<double>::infinity(), tFar = std::numeric_limits<double>::infinity();
  int axis = -1;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) {
      if (std::abs(o[i]) > 0.5) return std::nullopt;
      continue;
    }
    double t0 = (-0.5 - o[i]) / d[i], t1 = (0.5 - o[i]) / d[i];
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > tNear) {
      tNear = t0;
      axis = i;
    }
    tFar = std::min(tFar, t1);
  }
  if (axis < 0 || tNear > tFar || tNear <= 0.0) return std::nullopt;
  n = dvec3(0.0);
  n[axis] = d[axis] > 0.0 ? -1.0 : 1.0;
  return tNear;
}

}  // namespace

AnalyticScene::AnalyticScene(const Scene& scene) {
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (o.shape == pbr::Shape::Mesh) {
      throw SceneError(scene.name + ": objects[" + std::to_string(i) +
                       "]: a mesh has no exact shape (analytic geometry knows plane, sphere and box); "
                       "the mesh geometry renders it");
    }
    const glm::dmat4 toWorld(o.transform);
    const glm::dmat4 toObject = glm::inverse(toWorld);
    shapes_.push_back({o.shape, toObject, toWorld, glm::transpose(glm::dmat3(toObject))});
  }
}

std::optional<Hit> AnalyticScene::closestHit(const Ray& ray, double tMin, double tMax) const {
  std::optional<Hit> best;
  for (size_t i = 0; i < shapes_.size(); ++i) {
    const Shape& s = shapes_[i];
    // The object-space direction is not renormalised, so object-space t equals world-space t.
    const dvec3 o = dvec3(s.toObject * glm::dvec4(ray.origin, 1.0));
    const dvec3 d = dvec3(s.toObject * glm::dvec4(ray.direction, 0.0));
    dvec3 n;
    const std::optional<double> t = s.kind == pbr::Shape::Plane    ? hitPlane(o, d, n)
                                    : s.kind == pbr::Shape::Sphere ? hitSphere(o, d, n)
                                                                   : hitBox(o, d, n);
    if (!t || *t < tMin || *t > tMax || (best && *t >= best->t)) continue;
    best = Hit{*t, ray.origin + *t * ray.direction, glm::normalize(s.normalToWorld * n), i};
  }
  return best;
}

dvec3 cameraDirection(const Camera& camera, int width, int height, double px, double py) {
  // glm::lookAtRH's basis: the camera looks down -z, x is right, y is up.
  const dvec3 forward = glm::normalize(dvec3(camera.target) - dvec3(camera.position));
  const dvec3 right = glm::normalize(glm::cross(forward, dvec3(camera.up)));
  const dvec3 up = glm::cross(right, forward);
  const double tanHalf = std::tan(glm::radians(double(camera.fovYDeg)) * 0.5);
  const double aspect = double(width) / double(height);
  const double ndcX = px / width * 2.0 - 1.0;
  const double ndcY = 1.0 - py / height * 2.0;
  return forward + ndcX * aspect * tanHalf * right + ndcY * tanHalf * up;
}

Ray cameraRay(const Camera& camera, int width, int height, int x, int y) {
  return {dvec3(camera.position), glm::normalize(cameraDirection(camera, width, height, x + 0.5, y + 0.5))};
}

}  // namespace pbr::reference
