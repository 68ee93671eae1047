#include "reference/plane_reference.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "reference/directional_albedo.hpp"
#include "reference/point_light.hpp"
#include "reference/raycast.hpp"

namespace pbr::reference::plane {

namespace {

// Where the ray through the continuous image point (px, py), py counted down from the top edge, meets the
// plane; nullopt where it misses.
std::optional<dvec3> castRay(const Scene& scene, int width, int height, double px, double py) {
  const Ray ray = cameraRayAt(scene.camera, width, height, px, py);
  const dvec3 &eye = ray.origin, &dir = ray.direction;
  const Plane& plane = scene.plane;
  // The plane is one-sided (back faces are culled): seen from behind it is invisible.
  if (glm::dot(eye - plane.center, plane.normal) <= 0.0) return std::nullopt;
  const double denom = glm::dot(dir, plane.normal);
  if (denom >= 0.0) return std::nullopt;
  const double t = glm::dot(plane.center - eye, plane.normal) / denom;
  if (t < scene.camera.nearPlane || t > scene.camera.farPlane) return std::nullopt;
  const dvec3 p = eye + t * dir;
  const dvec3 axisV = glm::cross(plane.normal, plane.axisU);
  if (std::abs(glm::dot(p - plane.center, plane.axisU)) > plane.halfU) return std::nullopt;
  if (std::abs(glm::dot(p - plane.center, axisV)) > plane.halfV) return std::nullopt;
  return p;
}

// Classifies every pixel and shades the Surface ones with shade(position, view direction).
template <class Shade>
Image render(const Scene& scene, int width, int height, Shade shade) {
  Image image{width, height, std::vector<Pixel>(static_cast<size_t>(width) * height)};
  // Rasterisers snap vertices to a 1/256-pixel grid or finer: rays 1/32 pixel away decide the coverage robustly.
  const double probe = 1.0 / 32.0;
  const double offsets[4][2] = {{-probe, 0.0}, {probe, 0.0}, {0.0, -probe}, {0.0, probe}};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      const std::optional<dvec3> hit = castRay(scene, width, height, px, py);
      Pixel& out = image.pixels[static_cast<size_t>(y) * width + x];
      out.kind = hit ? PixelKind::Surface : PixelKind::Sky;
      for (const auto& o : offsets) {
        const bool probeHits = castRay(scene, width, height, px + o[0], py + o[1]).has_value();
        if (probeHits != hit.has_value()) out.kind = PixelKind::Edge;
      }
      if (hit) {
        const dvec3 eye = cameraRayAt(scene.camera, width, height, px, py).origin;
        out.radiance = shade(*hit, glm::normalize(eye - *hit));
      }
    }
  }
  return image;
}

}  // namespace

Image renderPbr(const Scene& scene, int width, int height, Visibility visibility) {
  BrdfForms forms;
  forms.visibility = visibility;
  forms.fresnel = Fresnel::Schlick;
  // One material, so one table per frame: it can afford finer bins than renderReference's per-object tables.
  const AlbedoTable albedo(scene.material, forms, 256, 48);
  const dvec3& n = scene.plane.normal;
  return render(scene, width, height, [&](const dvec3& p, const dvec3& v) {
    dvec3 lo = scene.ambient * albedo(std::max(glm::dot(n, v), 1e-4));
    for (const PointLight& light : scene.lights) lo += reflectedRadiance(light, p, n, v, scene.material, forms);
    return lo;
  });
}

Image renderBlinnPhong(const Scene& scene, int width, int height, BlinnPhongLobe lobe) {
  const dvec3& n = scene.plane.normal;
  return render(scene, width, height, [&](const dvec3& p, const dvec3& v) {
    dvec3 lo = blinnPhongAmbient(scene.material);
    for (const PointLight& light : scene.lights) lo += blinnPhongLight(light, p, n, v, scene.material, lobe);
    return glm::clamp(lo, dvec3(0.0), dvec3(1.0));
  });
}

}  // namespace pbr::reference::plane
