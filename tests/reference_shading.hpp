#pragma once
// An independent double-precision CPU evaluation of the renderer's shading contract for one plane lit by point
// lights, ray-cast through pixel centres. It is written from the published equations and shares no code with the
// renderer (not even its enums), so that a GPU frame compared against it tests the renderer, not itself.
#include <limits>
#include <vector>

#include <glm/vec3.hpp>

namespace pbr::reference {

using glm::dvec3;

struct Camera {
  dvec3 position, target, up;
  double fovYDeg = 50.0;
  double nearPlane = 0.1, farPlane = 100.0;
};

// The plane through `center` with unit `normal`; it extends halfU along unit `axisU` (perpendicular to the normal)
// and halfV along normal x axisU, each infinite by default.
struct Plane {
  dvec3 center{0.0};
  dvec3 normal{0.0, 1.0, 0.0};
  dvec3 axisU{1.0, 0.0, 0.0};
  double halfU = std::numeric_limits<double>::infinity();
  double halfV = std::numeric_limits<double>::infinity();
};

struct Material {
  dvec3 baseColor;  // linear
  double roughness = 0.5;
  double metalness = 0.0;
};

struct PointLight {
  dvec3 position;
  double radius = 1.0;
  dvec3 color{1.0};
  double luminousPower = 100.0;
};

// BlinnPhongSG: the Blinn-Phong lobe (n.h)^n replaced by e^(n (n.h - 1)).
enum class Model { Pbr, BlinnPhong, BlinnPhongSG };
enum class SmithVisibility { HeightCorrelated, Hammon };

struct Scene {
  Camera camera;
  Plane plane;
  Material material;
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

Image render(const Scene& scene, int width, int height, Model model,
             SmithVisibility visibility = SmithVisibility::HeightCorrelated);

// Linear value of the 8-bit sRGB code k: base colours chosen this way survive the G-buffer's sRGB8 storage.
double srgbCodeToLinear(int k);
// Exact piecewise sRGB encoding (IEC 61966-2-1) of a value in [0,1].
double srgbEncode(double linear);
// Stephen Hill's fit of the ACES RRT + ODT (sRGB primaries in and out), clamped to [0,1].
dvec3 acesHill(const dvec3& color);

}  // namespace pbr::reference
