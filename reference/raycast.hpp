#pragma once
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/scene/scene.hpp"

namespace pbr::reference {

using glm::dvec3;

struct Ray {
  dvec3 origin;
  dvec3 direction;  // unit, but for cameraRayAt's
};

struct Hit {
  double t = 0.0;
  dvec3 position;
  dvec3 normal;  // unit shading normal; exact shapes' face the ray, interpolated ones may lean away at silhouettes
  size_t object = 0;
};

// A scene's geometry as the reference sees it: what a ray meets first, and whether a shadow ray meets anything.
class RayCaster {
 public:
  virtual ~RayCaster() = default;
  // The nearest surface the camera sees along the ray within [tMin, tMax]: the faces the rasterizer draws.
  virtual std::optional<Hit> closestHit(const Ray& ray, double tMin, double tMax) const = 0;
  // Whether the ray meets any surface that stops shadow rays (stopsShadowRays below) within [tMin, tMax],
  // front or back face: the GPU draws its shadow casters without back-face culling. Stops at the first found.
  virtual bool occluded(const Ray& ray, double tMin, double tMax) const = 0;
  // Where a ray inside object `object`'s volume leaves it: the nearest of its back faces along the ray within
  // [tMin, tMax], the hit's normal the outward one (KHR_materials_volume's boundary). None for an open mesh the ray
  // leaves through a hole, or a plane, which has no inside.
  virtual std::optional<Hit> exitHit(const Ray& ray, double tMin, double tMax, size_t object) const = 0;
  // The diagonal of a box around all the geometry, 0 for none: the scene's scale.
  virtual double extent() const = 0;
};

// Whether a surface of this material stops shadow rays: every one but a BLEND surface whose alpha factor is below
// kBlendShadowCutoff (0.5, core/scene/scene.hpp), where the GPU's shadow maps cut BLEND casters out (textures are not
// read here, so the factor decides for the whole surface; MASK surfaces are solid for the same reason), and a
// transmissive one that lets more than kTransmissionShadowCutoff through (passesShadowRays), which the shadow maps
// leave out.
bool stopsShadowRays(const Material& material);

// The analytic shapes of a scene, each with its transform inverted once, intersected exactly in double.
// Camera rays meet front faces only, as the rasterizer culls back faces (a plane seen from below is not there).
class AnalyticScene final : public RayCaster {
 public:
  // Throws SceneError when an object is not an analytic shape (plane, sphere, box).
  explicit AnalyticScene(const Scene& scene);
  std::optional<Hit> closestHit(const Ray& ray, double tMin, double tMax) const override;
  bool occluded(const Ray& ray, double tMin, double tMax) const override;
  std::optional<Hit> exitHit(const Ray& ray, double tMin, double tMax, size_t object) const override;
  double extent() const override { return extent_; }

 private:
  struct Shape {
    pbr::Shape kind;
    glm::dmat4 toObject;
    glm::dmat4 toWorld;
    glm::dmat3 normalToWorld;
    bool stopsShadowRays;
  };
  std::vector<Shape> shapes_;
  double extent_ = 0.0;
};

// The camera's ray through the continuous image point (px, py), py counted down from the top edge, its direction
// unnormalised: its component along the view axis is 1, so a ray parameter along it is the depth that the near
// and far planes clip. Perspective rays leave the camera's position; orthographic ones leave the point of the
// camera's plane that the image point shows, all along the view axis.
Ray cameraRayAt(const Camera& camera, int width, int height, double px, double py);
// The ray through the centre of pixel (x, y), rows counted from the top, for the scene camera.
Ray cameraRay(const Camera& camera, int width, int height, int x, int y);

}  // namespace pbr::reference
