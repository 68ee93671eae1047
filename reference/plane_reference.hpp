#pragma once
#include <limits>
#include <vector>

#include <glm/vec3.hpp>

#include "core/scene/scene.hpp"
#include "reference/blinn_phong.hpp"
#include "reference/reference_brdf.hpp"

namespace pbr::reference::plane {

// One plane lit by point lights and uniform ambient light, ray-cast through pixel centres in double precision and
// shaded by the renderer's contract with the reference's terms: the frame that the renderer's frame of the same
// plane is compared with pixel by pixel. Unlike renderReference it marks the pixels whose coverage a rasterizer may
// decide either way, and it renders the Blinn-Phong model too.

// The plane through `center` with unit `normal`; it extends halfU along unit `axisU` (perpendicular to the normal)
// and halfV along normal x axisU, each infinite by default.
struct Plane {
  dvec3 center{0.0};
  dvec3 normal{0.0, 1.0, 0.0};
  dvec3 axisU{1.0, 0.0, 0.0};
  double halfU = std::numeric_limits<double>::infinity();
  double halfV = std::numeric_limits<double>::infinity();
};

struct Scene {
  Camera camera;
  Plane plane;
  ReferenceMaterial material;
  std::vector<PointLight> lights;
  dvec3 ambient{0.0};
};

// Sky: the pixel's ray misses the plane (or hits it outside [near, far]). Edge: rays a fraction of a pixel apart
// disagree, so rasterisation may legitimately go either way there and the pixel proves nothing.
enum class PixelKind { Sky, Surface, Edge };

struct Pixel {
  PixelKind kind = PixelKind::Sky;
  dvec3 radiance{0.0};  // for Surface pixels: HDR radiance (PBR) or the clamped LDR colour (Blinn-Phong)
};

struct Image {
  int width = 0, height = 0;
  std::vector<Pixel> pixels;  // rows from the top
  const Pixel& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

// The PBR model with the renderer's standard forms, Schlick's Fresnel and Lambert weighted by (1 - F(n.v)), and
// the given Smith visibility.
Image renderPbr(const Scene& scene, int width, int height,
                Visibility visibility = Visibility::HeightCorrelated);
Image renderBlinnPhong(const Scene& scene, int width, int height, BlinnPhongLobe lobe = BlinnPhongLobe::Power);

}  // namespace pbr::reference::plane
