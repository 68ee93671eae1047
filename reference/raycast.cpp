#include "reference/raycast.hpp"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "reference/bvh.hpp"

namespace pbr::reference {

namespace {

// Object-space intersections of the unit shapes (plane and sphere of diameter 1, box of side 1 about the origin).
// The ray parameters where a ray enters and leaves a solid shape; `axis` is the box's entering face, -1 for none.
struct Span {
  double enter, leave;
  int axis = -1;
};

// Where the ray crosses the plane's square, from either side.
std::optional<double> planeCrossing(const dvec3& o, const dvec3& d) {
  if (d.y == 0.0) return std::nullopt;
  const double t = -o.y / d.y;
  const dvec3 p = o + t * d;
  if (std::abs(p.x) > 0.5 || std::abs(p.z) > 0.5) return std::nullopt;
  return t;
}

std::optional<Span> sphereSpan(const dvec3& o, const dvec3& d) {
  const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - 0.25;
  const double disc = b * b - a * c;
  if (disc < 0.0) return std::nullopt;
  return Span{(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a};
}

// Slab test (Kay & Kajiya 1986).
std::optional<Span> boxSpan(const dvec3& o, const dvec3& d) {
  Span span{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) {
      if (std::abs(o[i]) > 0.5) return std::nullopt;
      continue;
    }
    double t0 = (-0.5 - o[i]) / d[i], t1 = (0.5 - o[i]) / d[i];
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > span.enter) {
      span.enter = t0;
      span.axis = i;
    }
    span.leave = std::min(span.leave, t1);
  }
  if (span.enter > span.leave) return std::nullopt;
  return span;
}

// Camera hits, front faces only; `n` receives the object-space outward normal.
std::optional<double> hitPlane(const dvec3& o, const dvec3& d, dvec3& n) {
  if (d.y >= 0.0 || o.y <= 0.0) return std::nullopt;  // front face (+Y) only
  n = dvec3(0, 1, 0);
  return planeCrossing(o, d);
}

std::optional<double> hitSphere(const dvec3& o, const dvec3& d, dvec3& n) {
  const std::optional<Span> span = sphereSpan(o, d);
  if (!span || span->enter <= 0.0) return std::nullopt;  // the entering root: front faces only
  n = glm::normalize(o + span->enter * d);
  return span->enter;
}

std::optional<double> hitBox(const dvec3& o, const dvec3& d, dvec3& n) {
  const std::optional<Span> span = boxSpan(o, d);
  if (!span || span->axis < 0 || span->enter <= 0.0) return std::nullopt;  // entering face only
  n = dvec3(0.0);
  n[span->axis] = d[span->axis] > 0.0 ? -1.0 : 1.0;
  return span->enter;
}

// Whether the shape's surface, either face, lies along the ray within [tMin, tMax].
bool crosses(pbr::Shape kind, const dvec3& o, const dvec3& d, double tMin, double tMax) {
  auto within = [&](double t) { return t >= tMin && t <= tMax; };
  if (kind == pbr::Shape::Plane) {
    const std::optional<double> t = planeCrossing(o, d);
    return t && within(*t);
  }
  const std::optional<Span> span = kind == pbr::Shape::Sphere ? sphereSpan(o, d) : boxSpan(o, d);
  return span && (within(span->enter) || within(span->leave));
}

// Object-space ray of a shape. Its direction is not renormalised, so object-space t equals world-space t.
Ray objectRay(const glm::dmat4& toObject, const Ray& ray) {
  return {dvec3(toObject * glm::dvec4(ray.origin, 1.0)), dvec3(toObject * glm::dvec4(ray.direction, 0.0))};
}

}  // namespace

bool stopsShadowRays(const Material& material) {
  return (material.alphaMode != AlphaMode::Blend || material.alpha >= kBlendShadowCutoff) &&
         !passesShadowRays(material);
}

AnalyticScene::AnalyticScene(const Scene& scene) {
  Aabb bounds;  // of the shapes' unit boxes
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (o.shape == pbr::Shape::Mesh) {
      throw SceneError(scene.name + ": objects[" + std::to_string(i) +
                       "]: a mesh has no exact shape (analytic geometry knows plane, sphere and box); "
                       "the mesh geometry renders it");
    }
    const glm::dmat4 toWorld(o.transform);
    const glm::dmat4 toObject = glm::inverse(toWorld);
    shapes_.push_back({o.shape, toObject, toWorld, glm::transpose(glm::dmat3(toObject)), stopsShadowRays(o.material)});
    for (int corner = 0; corner < 8; ++corner) {
      const dvec3 unit(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);  // a corner of the box [0, 1]^3
      bounds.grow(dvec3(toWorld * glm::dvec4(unit - 0.5, 1.0)));
    }
  }
  extent_ = bounds.diagonal();
}

std::optional<Hit> AnalyticScene::closestHit(const Ray& ray, double tMin, double tMax) const {
  std::optional<Hit> best;
  for (size_t i = 0; i < shapes_.size(); ++i) {
    const Shape& s = shapes_[i];
    const auto [o, d] = objectRay(s.toObject, ray);
    dvec3 n;
    const std::optional<double> t = s.kind == pbr::Shape::Plane    ? hitPlane(o, d, n)
                                    : s.kind == pbr::Shape::Sphere ? hitSphere(o, d, n)
                                                                   : hitBox(o, d, n);
    if (!t || *t < tMin || *t > tMax || (best && *t >= best->t)) continue;
    best = Hit{*t, ray.origin + *t * ray.direction, glm::normalize(s.normalToWorld * n), i};
  }
  return best;
}

std::optional<Hit> AnalyticScene::exitHit(const Ray& ray, double tMin, double tMax, size_t object) const {
  const Shape& s = shapes_.at(object);
  if (s.kind == pbr::Shape::Plane) return std::nullopt;
  const auto [o, d] = objectRay(s.toObject, ray);
  const std::optional<Span> span = s.kind == pbr::Shape::Sphere ? sphereSpan(o, d) : boxSpan(o, d);
  if (!span || span->leave < tMin || span->leave > tMax) return std::nullopt;
  const dvec3 p = o + span->leave * d;
  dvec3 n = p;  // a sphere's outward normal, or for the box the axis of the face it leaves through
  if (s.kind == pbr::Shape::Box) {
    int axis = 0;
    for (int i = 1; i < 3; ++i) axis = std::abs(p[i]) > std::abs(p[axis]) ? i : axis;
    n = dvec3(0.0);
    n[axis] = p[axis] > 0.0 ? 1.0 : -1.0;
  }
  return Hit{span->leave, ray.origin + span->leave * ray.direction, glm::normalize(s.normalToWorld * n), object};
}

bool AnalyticScene::occluded(const Ray& ray, double tMin, double tMax) const {
  for (const Shape& s : shapes_) {
    if (!s.stopsShadowRays) continue;
    const auto [o, d] = objectRay(s.toObject, ray);
    if (crosses(s.kind, o, d, tMin, tMax)) return true;
  }
  return false;
}

Ray cameraRayAt(const Camera& camera, int width, int height, double px, double py) {
  // glm::lookAtRH's basis: the camera looks down -z, x is right, y is up.
  const dvec3 forward = glm::normalize(dvec3(camera.target) - dvec3(camera.position));
  const dvec3 right = glm::normalize(glm::cross(forward, dvec3(camera.up)));
  const dvec3 up = glm::cross(right, forward);
  const double aspect = double(width) / double(height);
  const double ndcX = px / width * 2.0 - 1.0;
  const double ndcY = 1.0 - py / height * 2.0;
  if (camera.orthographic) {
    const double h = camera.orthoHalfHeight;
    return {dvec3(camera.position) + ndcX * aspect * h * right + ndcY * h * up, forward};
  }
  const double tanHalf = std::tan(glm::radians(double(camera.fovYDeg)) * 0.5);
  return {dvec3(camera.position), forward + ndcX * aspect * tanHalf * right + ndcY * tanHalf * up};
}

Ray cameraRay(const Camera& camera, int width, int height, int x, int y) {
  const Ray ray = cameraRayAt(camera, width, height, x + 0.5, y + 0.5);
  return {ray.origin, glm::normalize(ray.direction)};
}

}  // namespace pbr::reference
