#pragma once
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "core/scene/image.hpp"
#include "core/scene/sky_params.hpp"

namespace pbr {

// The light arriving from every direction, before any precomputation: an equirectangular image or a procedural
// sky, scaled by `intensity` and turned by `rotationDeg` about +Y (right-handed: at 90 degrees what lay towards
// +Z lies towards +X).
class Environment {
 public:
  // A Radiance .hdr or OpenEXR .exr file (readEnvironmentImage); throws std::runtime_error naming the file when it
  // cannot be used.
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
