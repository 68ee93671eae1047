#include "app/frame_notes.hpp"

#include <cstdio>
#include <string>

#include "core/scene/bounds.hpp"

namespace pbr {

namespace {

// The shares of a display image's pixels at full white in every channel, and within 2% of white in at least one:
// the tone curves approach white without reaching it, so a highlight compressed that far has lost its detail.
constexpr int kNearWhite = 250;

struct Clipping {
  double white = 0.0, clipped = 0.0;
};

Clipping clipping(const ImageRgba8& image) {
  size_t white = 0, clipped = 0;
  for (size_t i = 0; i + 3 < image.pixels.size(); i += 4) {
    const uint8_t* p = &image.pixels[i];
    white += p[0] == 255 && p[1] == 255 && p[2] == 255;
    clipped += p[0] >= kNearWhite || p[1] >= kNearWhite || p[2] >= kNearWhite;
  }
  const double pixels = double(image.pixels.size() / 4);
  return image.pixels.empty() ? Clipping{} : Clipping{double(white) / pixels, double(clipped) / pixels};
}

}  // namespace

std::vector<std::string> frameNotes(const Scene& scene, glm::ivec2 size, const FrameExposure& exposure,
                                    const ImageRgba8* ldr) {
  std::vector<std::string> notes;
  if (!scene.objects.empty()) {
    const Camera& camera = scene.camera;
    const FrustumPlanes view = frustumPlanes(camera.projection(float(size.x) / float(size.y)) * camera.view());
    bool seen = false;
    for (size_t i = 0; i < scene.objects.size() && !seen; ++i) {
      const SceneObject& o = scene.objects[i];
      seen = !outsideFrustum(view, meshBounds(scene.meshes.at(size_t(o.mesh)), o.transform));
    }
    if (!seen) {
      notes.push_back("no object of the scene lies in the camera's view (between its near and far planes): the "
                      "frame shows the background alone");
    }
  }
  // Over 99 % white: nothing of the scene can be told apart. Over kClippedShareNoted clipped: the highlights are
  // lost.
  if (ldr) {
    const Clipping c = clipping(*ldr);
    const std::string hint = exposure.metered ? "" : "; --exposure auto meters it from the frame";
    const char* clamped = "the blinn-phong model adds its light in LDR and clamps it, with no exposure to lower";
    char text[240];
    if (c.white > 0.99 && exposure.applies) {
      std::snprintf(text, sizeof text, "%.1f%% of the frame clips to white: an exposure of %g is too high for this "
                    "scene (--exposure, --ev100)%s", 100.0 * c.white, double(exposure.value), hint.c_str());
      notes.push_back(text);
    } else if (c.white > 0.99) {
      std::snprintf(text, sizeof text, "%.1f%% of the frame clips to white: %s", 100.0 * c.white, clamped);
      notes.push_back(text);
    } else if (c.clipped > kClippedShareNoted && exposure.applies) {
      std::snprintf(text, sizeof text, "%.1f%% of the frame's pixels clip (a channel at 250 or more) at exposure %g%s",
                    100.0 * c.clipped, double(exposure.value), hint.c_str());
      notes.push_back(text);
    } else if (c.clipped > kClippedShareNoted) {
      std::snprintf(text, sizeof text, "%.1f%% of the frame's pixels clip (a channel at 250 or more): %s",
                    100.0 * c.clipped, clamped);
      notes.push_back(text);
    }
  }
  return notes;
}

}  // namespace pbr
