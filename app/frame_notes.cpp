#include "app/frame_notes.hpp"

#include <cstdio>

#include "core/bounds.hpp"

namespace pbr {

namespace {

// The share of a display image's pixels at full white in every channel.
double whiteShare(const ImageRgba8& image) {
  size_t white = 0;
  for (size_t i = 0; i + 3 < image.pixels.size(); i += 4) {
    white += image.pixels[i] == 255 && image.pixels[i + 1] == 255 && image.pixels[i + 2] == 255;
  }
  return image.pixels.empty() ? 0.0 : double(white) / double(image.pixels.size() / 4);
}

}  // namespace

std::vector<std::string> frameNotes(const Scene& scene, glm::ivec2 size, float exposure, const ImageRgba8* ldr) {
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
  // Over 99 % clipped: nothing of the scene can be told apart.
  if (ldr) {
    const double white = whiteShare(*ldr);
    if (white > 0.99) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "%.1f%% of the frame clips to white: an exposure of %g is too high for this scene (--exposure, "
                    "--ev100)", 100.0 * white, double(exposure));
      notes.push_back(text);
    }
  }
  return notes;
}

}  // namespace pbr
