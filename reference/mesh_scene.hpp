#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "core/scene/scene.hpp"
#include "reference/bvh.hpp"
#include "reference/raycast.hpp"

namespace pbr::reference {

// The triangles the rasterizer draws, ray-cast in double: every object's mesh (Scene::meshes[object.mesh])
// placed by its transform, one BVH over all of them. Hits carry the shading normal the G-buffer pass writes:
// vertex normals through the inverse transpose of the model matrix, interpolated with the hit's barycentrics
// (which equal the rasterizer's perspective-correct ones at that point) and normalised. Back faces are culled
// unless the material is double-sided, whose back faces flip the normal; a mirroring transform swaps the winding
// that counts as front, as the G-buffer pass's glFrontFace does. Shadow rays meet both faces of every triangle of
// the objects that stop them (stopsShadowRays, raycast.hpp). Texture coordinates and maps are not used, so
// alpha-masked cut-outs are solid.
class MeshScene final : public RayCaster {
 public:
  // Throws SceneError when an object's mesh index names no mesh of the scene.
  explicit MeshScene(const Scene& scene);
  std::optional<Hit> closestHit(const Ray& ray, double tMin, double tMax) const override;
  bool occluded(const Ray& ray, double tMin, double tMax) const override;
  std::optional<Hit> exitHit(const Ray& ray, double tMin, double tMax, size_t object) const override;
  double extent() const override { return extent_; }

 private:
  struct Object {
    std::vector<dvec3> positions;  // world space
    std::vector<dvec3> normals;    // world space, not normalised: the vertex shader's output
    const std::vector<uint32_t>* indices = nullptr;
    double frontSign = 1.0;  // -1 where the transform mirrors: the winding of front faces is reversed
    bool doubleSided = false;
    bool stopsShadowRays = true;
  };
  struct Triangle {
    uint32_t object;
    uint32_t firstIndex;
  };
  // Where the ray crosses the triangle within [tMin, tMax]: t, the barycentrics u and v of its second and third
  // vertices, and whether the face met is the front one. Back faces count only with `bothFaces`.
  struct Crossing {
    double t, u, v;
    bool front;
  };
  std::optional<Crossing> cross(const Triangle& triangle, const Ray& ray, double tMin, double tMax,
                                bool bothFaces) const;
  std::optional<Hit> hitTriangle(const Triangle& triangle, const Ray& ray, double tMin, double tMax) const;

  std::vector<Object> objects_;
  std::vector<Triangle> triangles_;
  Bvh bvh_;
  double extent_ = 0.0;
};

}  // namespace pbr::reference
