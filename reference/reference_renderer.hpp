#pragma once
#include <functional>
#include <string>
#include <vector>

#include "core/scene/image.hpp"
#include "core/scene/scene.hpp"
#include "reference/reference_brdf.hpp"

namespace pbr::reference {

// Renders a scene lit by point and directional lights and uniform ambient light by ray-casting each pixel centre in
// double precision and evaluating the reference PBR model (reference_brdf.hpp) with the renderer's light units and
// attenuation. The uniform ambient term is exact: ambient radiance times the BRDF's directional albedo, integrated
// numerically. By default it ray-casts the triangles the GPU rasterizes (mesh_scene.hpp), so that a comparison
// measures shading alone; Geometry::Analytic ray-casts the exact shapes (plane, sphere, box) instead, and the
// difference between the two frames is the tessellation's error. Textures are ignored: material factors only, the
// alpha factor included. A surface of a BLEND material is a layer the camera ray crosses: each is shaded as an
// opaque one, radiance L_i, and composited front to back, "over" (Porter & Duff 1984), with its alpha factor a_i,
// C += T a_i L_i and T *= 1 - a_i from T = 1, in the exact depth order of the surfaces along the ray, until the
// first OPAQUE or MASK surface adds T L and ends it; a ray that leaves the scene adds nothing. Emission is added
// for no surface.
// With ReferenceOptions::shadows, a light that casts shadows adds nothing where a shadow ray towards it meets any
// surface that stops shadow rays (either face; alpha-masked cut-outs are solid, as textures are not read; BLEND
// surfaces only where their alpha factor is at least 0.5, stopsShadowRays in raycast.hpp). Throws SceneError for
// scenes with an environment rather than render them without it, and, with analytic geometry, for objects that
// are meshes rather than shapes.
struct ReferenceFrame {
  ImageRgbaF radiance;          // linear, before exposure, rows from the top like the renderer's HDR capture
  // Per pixel: the first object the camera ray meets, a BLEND layer's where one lies in front of the opaque
  // surface, -1 for none: a silhouette (interior()) is where the nearest surface changes, seen through or not.
  std::vector<int> objectIds;
  // Per pixel, with ReferenceOptions::shadows other than None (empty otherwise): the share of the lights that cast
  // shadows and add to the pixel's first surface (n.l > 0 and attenuation > 0, spot cone included) that reach it
  // unoccluded, each counting 0 or 1; -1 where no such light adds to it or the ray hits nothing.
  std::vector<float> visibility;
  // Pixels whose camera ray met more than kMaxBlendLayers BLEND layers: the surfaces beyond them are dropped.
  int truncatedRays = 0;
  // Whether the pixel and its 8 neighbours see the same object: comparisons skip silhouettes, where a
  // tessellated mesh and the exact shape, or a rasterizer's and a ray's rounding, cover different pixels.
  bool interior(int x, int y) const;
};

// The BLEND layers one camera ray composites at most: a bound on the walk, beyond what a real scene stacks in front
// of one pixel (ReferenceFrame::truncatedRays counts the rays that reach it).
constexpr int kMaxBlendLayers = 64;

enum class Geometry {
  Meshes,    // each object's triangle mesh, as rasterized
  Analytic,  // the exact shape each object's mesh tessellates
};
// "meshes" or "analytic"; throws std::invalid_argument otherwise.
Geometry parseGeometry(const std::string& name);
const char* toString(Geometry geometry);

// How the reference renders; each field is one independent axis of what is compared.
struct ReferenceOptions {
  int threads = 0;  // 0: every hardware thread
  BrdfForms forms;  // the BRDF's terms, for lights and ambient alike
  Geometry geometry = Geometry::Meshes;
  // Which lights cast shadows (core/scene/scene.hpp's castsShadows); none by default, the frames measured before shadows.
  ShadowMode shadows = ShadowMode::None;
  // Called from the worker threads (at once by several) as rows finish, with the share of the frame done.
  std::function<void(double)> progress;
};
ReferenceFrame renderReference(const Scene& scene, int width, int height, const ReferenceOptions& options = {});

}  // namespace pbr::reference
