#pragma once
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/image.hpp"
#include "core/scene.hpp"

namespace pbr {

// What a headless render says of a frame that would otherwise look wrong without a word: a scene whose objects
// all lie outside the camera's view (behind it, past its far plane, or beside it), and, given the display image, a
// frame that all but entirely clips to white (an exposure far too high) or whose pixels clip in more than
// kClippedShareNoted of them, with the hint of --exposure auto unless `autoExposure` chose `exposure`. Empty when
// none holds.
constexpr double kClippedShareNoted = 0.05;
std::vector<std::string> frameNotes(const Scene& scene, glm::ivec2 size, float exposure, bool autoExposure,
                                    const ImageRgba8* ldr);

}  // namespace pbr
