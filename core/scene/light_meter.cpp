#include "core/scene/light_meter.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace pbr {

namespace {

double luminance(const glm::vec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

// The distance window of the renderer's attenuation, clamp(1 - (d/R)^4, 0, 1)^2.
double window(double d, double radius) {
  if (radius <= 0.0) return 0.0;
  const double x = d / radius, w = std::clamp(1.0 - x * x * x * x, 0.0, 1.0);
  return w * w;
}

}  // namespace

double incidentIlluminance(const Scene& scene, const glm::vec3& point, float nearest) {
  constexpr double kPi = 3.14159265358979323846;
  double lux = 0.0;
  for (const PointLight& light : scene.lights) {
    const glm::vec3 toPoint = point - light.position;
    const double d = glm::length(toPoint);
    double falloff = window(std::max(d - nearest, 0.0), light.radius);
    if (light.spot && d > 0.0) {
      const SpotFalloff s = spotFalloff(*light.spot);
      const double cosAngle = glm::dot(light.spot->direction, toPoint) / d;
      const double x = std::clamp(cosAngle * s.scale + s.offset, 0.0, 1.0);
      falloff *= x * x;
    }
    const double r = std::max(d, static_cast<double>(nearest));
    lux += light.luminousPower / (4.0 * kPi) * luminance(light.color) * falloff / (r * r);
  }
  for (const DirectionalLight& sun : scene.directionalLights) lux += sun.illuminance * luminance(sun.color);
  return lux;
}

double ev100FromIlluminance(double lux) { return std::log2(lux * 100.0 / 250.0); }

}  // namespace pbr
