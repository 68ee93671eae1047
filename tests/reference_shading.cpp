#include "tests/reference_shading.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "reference/directional_albedo.hpp"

namespace pbr::reference {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Where the ray through the continuous image point (px, py), py counted down from the top edge, meets the
// plane; nullopt where it misses.
std::optional<dvec3> castRay(const Scene& scene, int width, int height, double px, double py) {
  const Camera& cam = scene.camera;
  // glm::lookAtRH's basis: the camera looks down -z, x is right, y is up.
  const dvec3 forward = glm::normalize(cam.target - cam.position);
  const dvec3 right = glm::normalize(glm::cross(forward, cam.up));
  const dvec3 up = glm::cross(right, forward);
  const double tanHalf = std::tan(cam.fovYDeg * kPi / 360.0);
  const double aspect = static_cast<double>(width) / height;
  const double ndcX = px / width * 2.0 - 1.0;
  const double ndcY = 1.0 - py / height * 2.0;
  // Unnormalised so that the ray parameter t is the depth along the view axis, which near/far clip.
  const dvec3 dir = forward + ndcX * tanHalf * aspect * right + ndcY * tanHalf * up;

  const Plane& plane = scene.plane;
  // The plane is one-sided (back faces are culled): seen from behind it is invisible.
  if (glm::dot(cam.position - plane.center, plane.normal) <= 0.0) return std::nullopt;
  const double denom = glm::dot(dir, plane.normal);
  if (denom >= 0.0) return std::nullopt;
  const double t = glm::dot(plane.center - cam.position, plane.normal) / denom;
  if (t < cam.nearPlane || t > cam.farPlane) return std::nullopt;
  const dvec3 p = cam.position + t * dir;
  const dvec3 axisV = glm::cross(plane.normal, plane.axisU);
  if (std::abs(glm::dot(p - plane.center, plane.axisU)) > plane.halfU) return std::nullopt;
  if (std::abs(glm::dot(p - plane.center, axisV)) > plane.halfV) return std::nullopt;
  return p;
}

// Windowed inverse-square falloff (Karis 2013), capped at 1; R <= 0 reaches nothing (the window's limit).
double windowedAttenuation(double d, double radius) {
  if (!(radius > 0.0)) return 0.0;
  const double x4 = std::pow(d / radius, 4.0);
  const double window = std::clamp(1.0 - x4, 0.0, 1.0);
  return std::min(window * window / std::pow(std::max(d, 0.01), 2.0), 1.0);
}

dvec3 f0Of(const Material& m) { return glm::mix(dvec3(0.04), m.baseColor, m.metalness); }

// The plane's one material's directional albedo over n.v, tabulated once per frame: per pixel it would cost
// seconds. 256 bins, linear between them, of the CPU reference library's integral.
class AlbedoTable {
 public:
  AlbedoTable(const Material& m, SmithVisibility visibility) {
    BrdfForms forms;
    forms.fresnel = BrdfForms::Fresnel::Schlick;
    forms.visibility = visibility == SmithVisibility::HeightCorrelated ? BrdfForms::Visibility::HeightCorrelated
                                                                       : BrdfForms::Visibility::Hammon;
    for (int i = 0; i < kBins; ++i) {
      values_[i] = directionalAlbedo({m.baseColor, m.roughness, m.metalness}, std::max(double(i) / (kBins - 1), 1e-4),
                                     forms, 48);
    }
  }
  dvec3 operator()(double nv) const {
    const double x = std::clamp(nv, 0.0, 1.0) * (kBins - 1);
    const int i = std::min(int(x), kBins - 2);
    return glm::mix(values_[i], values_[i + 1], x - i);
  }

 private:
  static constexpr int kBins = 256;
  dvec3 values_[kBins];
};

dvec3 shadePbr(const Scene& scene, const AlbedoTable& albedo, const dvec3& p, const dvec3& n, const dvec3& v,
               SmithVisibility visibility) {
  const Material& m = scene.material;
  const dvec3 f0 = f0Of(m);
  // Uniform ambient radiance times the BRDF's directional albedo.
  dvec3 lo = scene.ambient * albedo(std::max(glm::dot(n, v), 1e-4));
  const double a = m.roughness * m.roughness;
  const double a2 = a * a;
  const double nv = glm::dot(n, v);
  for (const PointLight& light : scene.lights) {
    const dvec3 toLight = light.position - p;
    const double d = glm::length(toLight);
    const dvec3 l = toLight / d;
    const double nl = glm::dot(n, l);
    if (nl <= 0.0) continue;
    const dvec3 h = glm::normalize(v + l);
    const double nh = glm::dot(n, h);
    const double vh = glm::dot(v, h);
    const double dTerm = a2 / (kPi * std::pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
    const double vTerm =
        visibility == SmithVisibility::HeightCorrelated
            ? 0.5 / (nl * std::sqrt(nv * nv * (1.0 - a2) + a2) + nv * std::sqrt(nl * nl * (1.0 - a2) + a2))
            : 0.5 / ((1.0 - a) * 2.0 * nl * nv + a * (nl + nv));  // Hammon 2017
    const dvec3 f = f0 + (dvec3(1.0) - f0) * std::pow(1.0 - vh, 5.0);
    const dvec3 fs = dTerm * vTerm * f;
    const dvec3 fView = f0 + (dvec3(1.0) - f0) * std::pow(1.0 - nv, 5.0);
    const dvec3 fd = (dvec3(1.0) - fView) * (1.0 - m.metalness) * m.baseColor / kPi;
    const double intensity = light.luminousPower / (4.0 * kPi);
    lo += (fd + fs) * light.color * intensity * windowedAttenuation(d, light.radius) * nl;
  }
  return lo;
}

dvec3 shadeBlinnPhong(const Scene& scene, const dvec3& p, const dvec3& n, const dvec3& v, bool gaussianLobe) {
  const Material& m = scene.material;
  const dvec3 diffuse = m.baseColor * (1.0 - m.metalness);
  const dvec3 specular = f0Of(m);
  const double a = m.roughness * m.roughness;
  const double shininess = 2.0 / (a * a) - 2.0;
  dvec3 lo = 0.02 * diffuse;
  for (const PointLight& light : scene.lights) {
    const dvec3 toLight = light.position - p;
    const double d = glm::length(toLight);
    const dvec3 l = toLight / d;
    const double nl = glm::dot(n, l);
    if (nl <= 0.0) continue;
    const double nh = std::max(glm::dot(n, glm::normalize(v + l)), 0.0);
    const double lobe = gaussianLobe ? std::exp(shininess * (nh - 1.0)) : std::pow(nh, shininess);
    lo += (diffuse * nl + specular * lobe) * light.color * windowedAttenuation(d, light.radius);
  }
  return glm::clamp(lo, dvec3(0.0), dvec3(1.0));
}

}  // namespace

Image render(const Scene& scene, int width, int height, Model model, SmithVisibility visibility) {
  Image image{width, height, std::vector<Pixel>(static_cast<size_t>(width) * height)};
  const AlbedoTable albedo(scene.material, visibility);
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
      if (!hit) continue;
      const dvec3 v = glm::normalize(scene.camera.position - *hit);
      out.radiance = model == Model::Pbr ? shadePbr(scene, albedo, *hit, scene.plane.normal, v, visibility)
                                         : shadeBlinnPhong(scene, *hit, scene.plane.normal, v, model == Model::BlinnPhongSG);
    }
  }
  return image;
}

double srgbCodeToLinear(int k) {
  const double c = k / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double srgbEncode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

dvec3 acesHill(const dvec3& color) {
  // Hill's row-major matrices: out[i] = sum_j M[i][j] in[j].
  static const double kInput[3][3] = {
      {0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}};
  static const double kOutput[3][3] = {
      {1.60475, -0.53108, -0.07367}, {-0.10208, 1.10813, -0.00605}, {-0.00327, -0.07276, 1.07602}};
  const auto apply = [](const double (&m)[3][3], const dvec3& c) {
    return dvec3(m[0][0] * c.x + m[0][1] * c.y + m[0][2] * c.z, m[1][0] * c.x + m[1][1] * c.y + m[1][2] * c.z,
                 m[2][0] * c.x + m[2][1] * c.y + m[2][2] * c.z);
  };
  const dvec3 v = apply(kInput, color);
  const dvec3 a = v * (v + 0.0245786) - 0.000090537;
  const dvec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
  return glm::clamp(apply(kOutput, a / b), dvec3(0.0), dvec3(1.0));
}

}  // namespace pbr::reference
