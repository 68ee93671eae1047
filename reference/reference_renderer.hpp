#pragma once
#include <vector>

#include "core/image.hpp"
#include "core/scene.hpp"
#include "reference/reference_brdf.hpp"

namespace pbr::reference {

// Renders a scene of analytic shapes and point lights by ray-casting each pixel centre in double precision and
// evaluating the reference PBR model (reference_brdf.hpp) with the renderer's light units and attenuation. The
// uniform ambient term is exact: ambient radiance times the BRDF's directional albedo, integrated numerically.
// Throws SceneError for objects that are not analytic shapes and for
// scenes with an environment, rather than render them without it.
struct ReferenceFrame {
  ImageRgbaF radiance;          // linear, before exposure, rows from the top like the renderer's HDR capture
  std::vector<int> objectIds;   // per pixel: the object hit, -1 for none
  // Whether the pixel and its 8 neighbours see the same object: comparisons skip silhouettes, where a
  // tessellated mesh and the exact shape legitimately cover different pixels.
  bool interior(int x, int y) const;
};

// How the reference renders; each field is one independent axis of what is compared.
struct ReferenceOptions {
  int threads = 0;  // 0: every hardware thread
  BrdfForms forms;  // the BRDF's terms, for lights and ambient alike
};
ReferenceFrame renderReference(const Scene& scene, int width, int height, const ReferenceOptions& options = {});

}  // namespace pbr::reference
