#include "shadows/shadow_views.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

namespace pbr {

namespace {

// A matrix from its four rows.
glm::mat4 fromRows(const glm::vec4& r0, const glm::vec4& r1, const glm::vec4& r2, const glm::vec4& r3) {
  return glm::transpose(glm::mat4(r0, r1, r2, r3));
}

std::array<glm::vec3, 8> corners(const WorldBounds& b) {
  std::array<glm::vec3, 8> c;
  for (int i = 0; i < 8; ++i) {
    c[size_t(i)] = {i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z};
  }
  return c;
}

}  // namespace

bool frameAroundX(const glm::vec3& axis) { return !(std::abs(axis.y) < 0.99f); }

void frameAround(const glm::vec3& axis, glm::vec3& right, glm::vec3& up) {
  const glm::vec3 helper = frameAroundX(axis) ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  right = glm::normalize(glm::cross(axis, helper));
  up = glm::cross(right, axis);
}

CascadeSplits cascadeSplits(const Camera& camera, float nearDepth, float farDepth, int count) {
  CascadeSplits s;
  const float n = std::max(camera.nearPlane, nearDepth);
  if (!(std::min(camera.farPlane, farDepth) >= n)) return s;
  // Receivers at one depth (a plane seen head-on) still take shadows, from casters out of view: the cascades then
  // cover a thousandth of that depth.
  const float f = std::max(std::min(camera.farPlane, farDepth), n + std::max(n * 1e-3f, 1e-4f));
  constexpr float kLambda = 0.75f;
  s.count = count;
  s.begin = n;
  for (int i = 1; i <= count; ++i) {
    const float t = float(i) / float(count);
    s.ends[size_t(i - 1)] = kLambda * n * std::pow(f / n, t) + (1.0f - kLambda) * (n + (f - n) * t);
  }
  s.ends[size_t(count - 1)] = f;
  return s;
}

ShadowViewPlan cascadeView(const Camera& camera, float aspect, const CascadeSplits& splits, int cascade,
                           const glm::vec3& direction, const WorldBounds& scene, int size) {
  const float begin = cascade == 0 ? splits.begin : splits.ends[size_t(cascade - 1)];
  const float end = splits.ends[size_t(cascade)];
  glm::vec3 right, up;
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  frameAround(forward, right, up);
  // frameAround's up need not be the camera's: the slice's corners depend only on the frustum's extent.
  glm::vec3 centre(0.0f);
  std::array<glm::vec3, 8> slice;
  for (int i = 0; i < 8; ++i) {
    const float z = i & 4 ? end : begin;
    const glm::vec2 half = camera.halfExtent(z, aspect);
    slice[size_t(i)] = camera.position + forward * z + right * (half.x * (i & 1 ? 1.0f : -1.0f)) +
                       up * (half.y * (i & 2 ? 1.0f : -1.0f));
    centre += slice[size_t(i)] / 8.0f;
  }
  float radius = 0.0f;
  for (const glm::vec3& c : slice) radius = std::max(radius, glm::distance(c, centre));

  glm::vec3 lx, ly;
  const glm::vec3 d = glm::normalize(direction);
  frameAround(d, lx, ly);
  const float texel = 2.0f * radius / float(size);
  const float cx = std::floor(glm::dot(centre, lx) / texel) * texel;
  const float cy = std::floor(glm::dot(centre, ly) / texel) * texel;
  float tMin = 1e30f, tMax = -1e30f;
  for (const glm::vec3& c : corners(scene)) {
    tMin = std::min(tMin, glm::dot(c, d));
    tMax = std::max(tMax, glm::dot(c, d));
  }
  const float margin = 1e-3f * (tMax - tMin) + 1e-4f;
  tMin -= margin;
  tMax += margin;
  ShadowViewPlan v;
  // Reversed Z: depth 1 at the caster range's end nearest the light, 0 at its far end.
  v.viewProjection = fromRows(glm::vec4(lx / radius, -cx / radius), glm::vec4(ly / radius, -cy / radius),
                              glm::vec4(-d / (tMax - tMin), tMax / (tMax - tMin)), glm::vec4(0, 0, 0, 1));
  v.size = size;
  v.texelWorld = texel;
  return v;
}

ShadowViewPlan perspectiveView(const glm::vec3& apex, const glm::vec3& axis, float tanHalf, float radius, int size,
                               int border) {
  glm::vec3 right, up;
  frameAround(axis, right, up);
  const float t = tanHalf * float(size) / float(std::max(1, size - 2 * border));
  const float n = shadowNearPlane(radius);
  ShadowViewPlan v;
  // Reversed Z with the far plane at infinity: depth = n / w, w the distance along the axis.
  v.viewProjection = fromRows(glm::vec4(right / t, -glm::dot(apex, right) / t),
                              glm::vec4(up / t, -glm::dot(apex, up) / t), glm::vec4(0, 0, 0, n),
                              glm::vec4(axis, -glm::dot(apex, axis)));
  v.size = size;
  v.texelWorld = 2.0f * t / float(size);
  return v;
}

}  // namespace pbr
