#pragma once
#include <cstdint>
#include <utility>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/scene/scene.hpp"
#include "core/scene/shader_sources.hpp"
#include "core/scene/shading_model.hpp"
#include "core/scene/shadow_settings.hpp"
#include "lighting/gpu_lights.hpp"

namespace pbr {

// The GL objects the options hand the lighting pass, by handle (core/gl/).
class Texture;
struct EnvironmentMaps;
struct ShadowMaps;

// What the lighting pass (lighting_pass.hpp) shades a frame with. The options and the permutation they choose need
// no GL, so that the permutations can be listed and checked without a context.
struct LightingOptions {
  ShadingModel model = ShadingModel::Pbr;
  ShadingVariant variant;  // PBR only
  glm::vec3 ambient{0.0f};
  bool stats = false;  // count light-pixel pairs (evaluated, contributing) on the GPU
  // PBR only: image-based lighting from these maps replaces `ambient`, and pixels without geometry show the
  // environment. Null: uniform ambient light.
  const EnvironmentMaps* environment = nullptr;
  // Non-null: the pass also counts each pixel's light-pixel pairs into this RG32UI image of the frame's size
  // (evaluated, contributing), what the efficiency debug view shows.
  const Texture* pairCounts = nullptr;
  // Non-null: lights with shadow views in these maps are shaded with their visibility, sampled by this filter.
  const ShadowMaps* shadows = nullptr;
  ShadowFilter shadowFilter = ShadowFilter::Pcf3x3;
  // Non-null (with shadows): the pass also sums each pixel's light from casting lights into this RG32F image of the
  // frame's size (luminance with, and without, its shadows), what the shadows debug view shows.
  const Texture* shadowLight = nullptr;
  // The G-buffer holds unlit surfaces (hasUnlitSurface): pixels it flags so take no light.
  bool unlitSurfaces = false;
  // PBR only: the surfaces shaded have their own dielectric F0 and F90 (KHR_materials_ior, _specular), from the
  // G-buffer's specular channel (SurfaceTextures::specular) or the BLEND materials' blocks.
  bool specularMaterials = false;
  // PBR only: the surfaces shaded may have a clear coat (KHR_materials_clearcoat), likewise.
  bool clearcoatMaterials = false;
  // PBR only: the surfaces shaded may have a sheen (KHR_materials_sheen), likewise.
  bool sheenMaterials = false;
  // Transmissive surfaces (KHR_materials_transmission) shaded as if without the extension (MaterialLobes).
  bool transmissionOff = false;

  // Image-based lighting: a PBR frame with an environment.
  bool ibl() const { return model == ShadingModel::Pbr && environment != nullptr; }
};

// The material extensions' lobes a frame shades, each on unless switched off to compare a scene with and without
// it (the viewer's overlay): off, the lobe is shaded as for a material without the extension (the lighting passes'
// permutation leaves it out; the G-buffer keeps its channels).
struct MaterialLobes {
  bool specular = true;      // KHR_materials_ior / _specular: off, the core material's F0 0.04 and F90 1
  bool clearcoat = true;     // KHR_materials_clearcoat
  bool sheen = true;         // KHR_materials_sheen
  bool transmission = true;  // KHR_materials_transmission / _volume: off, the surface diffuses all it takes in
};
// The lobes some material of `scene` uses (every field false where none does): what there is to switch off.
MaterialLobes usedLobes(const Scene& scene);

// Light-pixel pairs a frame's lighting pass counted (LightingOptions::stats).
struct PairCounts {
  uint64_t evaluated = 0;
  uint64_t contributing = 0;  // attenuation > 0 and n.l > 0
  // The pass's 8x8-pixel tiles: those holding a surface, which it shades, and all of them.
  uint32_t surfaceTiles = 0, tiles = 0;
  glm::uvec2 surfaceGroups{0u};  // the workgroups of the dispatch that shades the surface tiles, along x and y
};

// Mirrors the head of the SurfaceTiles block (shaders/lighting/surface_tiles.glsl, std430): two indirect dispatches,
// the surface tiles' and the background tiles' (xyz their workgroups, grown as tiles are listed; w the tiles), and
// the grid of tiles.
struct SurfaceTilesHeader {
  glm::uvec4 surfaceDispatch{0u, 0u, 1u, 0u};
  glm::uvec4 backgroundDispatch{0u, 0u, 1u, 0u};
  glm::uvec4 tileGrid{0u};  // columns, tiles in all
};
static_assert(sizeof(SurfaceTilesHeader) == 48, "SurfaceTilesHeader must match its std430 layout");

// The image format qualifier (HDR_IMAGE_FORMAT) and the largest finite value (HDR_MAX) of a radiance target of
// `format`.
std::pair<const char*, const char*> radianceImageFormat(HdrFormat format);

// The defines of lighting/deferred.comp for these options (Blinn-Phong takes no PBR variant, nor IBL), on a radiance
// target of `radiance`'s format.
ShaderDefines lightingPermutation(const LightingOptions& options, bool clustered, HdrFormat radiance,
                                  bool chunked = false, LightKinds kinds = {},
                                  uint32_t lightWindow = kLightWindowMax);

}  // namespace pbr
