// What a headless render says of a frame that clips (app/frame_notes.*): the share of pixels near white, with the
// --exposure auto hint only where a fixed exposure applied, and for Blinn-Phong frames, which no exposure reaches,
// the model's clamp instead.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "app/frame_notes.hpp"

namespace {

// `white` of `pixels` pixels at (255, 255, 255), `bright` at (250, 10, 10), the rest grey.
pbr::ImageRgba8 frame(int pixels, int white, int bright) {
  pbr::ImageRgba8 image{pixels, 1, {}};
  for (int i = 0; i < pixels; ++i) {
    const bool w = i < white, b = !w && i < white + bright;
    image.pixels.insert(image.pixels.end(), {uint8_t(w ? 255 : b ? 250 : 128), uint8_t(w ? 255 : b ? 10 : 128),
                                             uint8_t(w ? 255 : b ? 10 : 128), 255});
  }
  return image;
}

}  // namespace

TEST_CASE("frame notes: clipping is named with the auto-exposure hint where a fixed exposure applied") {
  const pbr::Scene empty;  // no objects: nothing to say of the view
  const pbr::ImageRgba8 clipped = frame(100, 0, 6), fine = frame(100, 0, 5), white = frame(100, 100, 0);
  const pbr::FrameExposure fixed{true, 2.0f, false}, metered{true, 0.5f, true}, blinnPhong{false, 1.0f, false};
  CHECK(pbr::frameNotes(empty, {100, 1}, fixed, &fine).empty());  // 5 % is not over kClippedShareNoted
  CHECK(pbr::frameNotes(empty, {100, 1}, fixed, &clipped) ==
        std::vector<std::string>{"6.0% of the frame's pixels clip (a channel at 250 or more) at exposure 2; "
                                 "--exposure auto meters it from the frame"});
  CHECK(pbr::frameNotes(empty, {100, 1}, metered, &clipped) ==
        std::vector<std::string>{"6.0% of the frame's pixels clip (a channel at 250 or more) at exposure 0.5"});
  CHECK(pbr::frameNotes(empty, {100, 1}, blinnPhong, &clipped) ==
        std::vector<std::string>{"6.0% of the frame's pixels clip (a channel at 250 or more): the blinn-phong model "
                                 "adds its light in LDR and clamps it, with no exposure to lower"});
  CHECK(pbr::frameNotes(empty, {100, 1}, blinnPhong, &white) ==
        std::vector<std::string>{"100.0% of the frame clips to white: the blinn-phong model adds its light in LDR and "
                                 "clamps it, with no exposure to lower"});
  CHECK(pbr::frameNotes(empty, {100, 1}, fixed, nullptr).empty());
}
