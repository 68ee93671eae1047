#include "ibl/environment.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>

#include "ibl/openexr_image.hpp"

namespace pbr {

namespace {

bool nonNegative(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f;
}

}  // namespace

Environment::Environment(std::optional<ImageRgbaF> equirect, const SkyParams& sky, float intensity, float rotationDeg)
    : equirect_(std::move(equirect)), sky_(sky), intensity_(intensity), rotationDeg_(rotationDeg) {
  if (!std::isfinite(intensity) || intensity < 0.0f) {
    throw std::invalid_argument("environment intensity must be a finite number >= 0");
  }
  if (!std::isfinite(rotationDeg)) throw std::invalid_argument("environment rotation must be finite");
  if (equirect_) {
    const ImageRgbaF& image = *equirect_;
    if (image.width < 1 || image.height < 1 || image.pixels.size() != size_t{4} * image.width * image.height) {
      throw std::invalid_argument("equirectangular environment: pixels do not match its size");
    }
    return;
  }
  if (!nonNegative(sky.zenith) || !nonNegative(sky.horizon) || !nonNegative(sky.ground) ||
      !nonNegative(sky.sunRadiance)) {
    throw std::invalid_argument("sky radiance must be finite and >= 0");
  }
  const float length = glm::length(sky.sunDirection);
  if (!std::isfinite(length) || length <= 0.0f) throw std::invalid_argument("sky sun direction must be non-zero");
  if (!(sky.sunAngularRadiusDeg > 0.0f && sky.sunAngularRadiusDeg < 90.0f)) {
    throw std::invalid_argument("sky sun angular radius must be in (0, 90) degrees");
  }
}

Environment Environment::fromHdrFile(const std::string& path, float intensity, float rotationDeg) {
  return fromEquirect(readEnvironmentImage(path), intensity, rotationDeg);
}

Environment Environment::fromEquirect(ImageRgbaF image, float intensity, float rotationDeg) {
  return Environment(std::move(image), SkyParams{}, intensity, rotationDeg);
}

Environment Environment::sky(const SkyParams& params, float intensity, float rotationDeg) {
  return Environment(std::nullopt, params, intensity, rotationDeg);
}

Environment Environment::uniform(const glm::vec3& radiance) {
  SkyParams params;
  params.zenith = params.horizon = params.ground = radiance;
  params.sunRadiance = glm::vec3(0.0f);
  return sky(params);
}

const ImageRgbaF& Environment::equirect() const {
  if (!equirect_) throw std::logic_error("Environment::equirect: a procedural sky has no image");
  return *equirect_;
}

}  // namespace pbr
