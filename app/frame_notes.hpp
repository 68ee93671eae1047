#pragma once
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/scene/image.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

// How a frame reached its display values: PBR frames through an exposure (given, or metered from the frame) and
// a tone curve; Blinn-Phong frames add their light in LDR and clamp it, no exposure applying.
struct FrameExposure {
  bool applies = true;
  float value = 1.0f;
  bool metered = false;
};

// What a headless render says of a frame that would otherwise look wrong without a word: a scene whose objects
// all lie outside the camera's view (behind it, past its far plane, or beside it), and, given the display image, a
// frame that all but entirely clips to white (an exposure far too high) or whose pixels clip in more than
// kClippedShareNoted of them, with the hint of --exposure auto where a fixed exposure applied. Empty when none
// holds.
constexpr double kClippedShareNoted = 0.05;
std::vector<std::string> frameNotes(const Scene& scene, glm::ivec2 size, const FrameExposure& exposure,
                                    const ImageRgba8* ldr);

}  // namespace pbr
