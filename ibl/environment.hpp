#pragma once
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "core/image.hpp"

namespace pbr {

// A procedural sky for tests and scenes without an environment file: a gradient from the horizon up to the
// zenith and down to the ground (radiance, linear RGB), plus a sun disc of uniform radiance.
struct SkyParams {
  glm::vec3 zenith{0.12f, 0.25f, 0.6f};
  glm::vec3 horizon{0.6f, 0.7f, 0.85f};
  glm::vec3 ground{0.15f, 0.13f, 0.11f};
  glm::vec3 sunDirection{0.4f, 0.5f, -0.77f};  // towards the sun; need not be unit length
  float sunAngularRadiusDeg = 0.27f;           // the real sun's
  glm::vec3 sunRadiance{20000.0f};             // 0 for no sun
};

// The light arriving from every direction, before any precomputation: an equirectangular image or a procedural
// sky, scaled by `intensity` and turned by `rotationDeg` about +Y (right-handed: at 90 degrees what lay towards
// +Z lies towards +X).
class Environment {
 public:
  // A Radiance .hdr file (readRadianceHdr); throws std::runtime_error naming the file when it cannot be used.
  static Environment fromHdrFile(const std::string& path, float intensity = 1.0f, float rotationDeg = 0.0f);
  // Equirectangular radiance: rows from the top (+Y) to the bottom (-Y); the centre column looks along -Z, the
  // column at 3/4 of the width along +X.
  static Environment fromEquirect(ImageRgbaF image, float intensity = 1.0f, float rotationDeg = 0.0f);
  static Environment sky(const SkyParams& params, float intensity = 1.0f, float rotationDeg = 0.0f);
  // The same radiance from every direction: the white furnace.
  static Environment uniform(const glm::vec3& radiance);

  bool isSky() const { return !equirect_; }
  // Throws std::logic_error for a sky.
  const ImageRgbaF& equirect() const;
  const SkyParams& skyParams() const { return sky_; }
  float intensity() const { return intensity_; }
  float rotationDeg() const { return rotationDeg_; }

 private:
  Environment(std::optional<ImageRgbaF> equirect, const SkyParams& sky, float intensity, float rotationDeg);

  std::optional<ImageRgbaF> equirect_;
  SkyParams sky_;
  float intensity_, rotationDeg_;
};

}  // namespace pbr
