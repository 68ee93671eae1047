#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/gl/blended_surfaces.hpp"
#include "core/gl/environment_maps.hpp"
#include "core/scene/frame_block.hpp"
#include "core/gl/program_cache.hpp"
#include "core/gl/shadow_maps.hpp"
#include "core/gl/uniform_buffer.hpp"
#include "lighting/ambient_albedo.hpp"
#include "lighting/light_buffer.hpp"
#include "lighting/light_clusters.hpp"
#include "lighting/lighting_options.hpp"
#include "core/scene/shading_model.hpp"

namespace pbr {

// std140 mirror of `LightingBlock` in shaders/lighting/lights.glsl.
struct LightingBlock {
  glm::vec4 ambient;
  glm::uvec4 counts;  // x: lights in the frame
};
static_assert(sizeof(LightingBlock) == 32, "LightingBlock must match its std140 layout");

// The G-buffer channels the lighting pass reads, as plain textures: lighting knows no geometry pass.
struct SurfaceTextures {
  const Texture& baseColor;
  const Texture& normal;
  const Texture& material;
  const Texture& depth;
  // The dielectric's F0 / 0.04 and F90 (KHR_materials_ior, _specular), where the G-buffer's layout has them: the
  // PBR lighting pass then shades with them (MATERIAL_SPECULAR).
  const Texture* specular = nullptr;
  // The clearcoat's strength, roughness and normal (KHR_materials_clearcoat), likewise (MATERIAL_CLEARCOAT).
  const Texture* clearcoat = nullptr;
  // The sheen's colour and roughness (KHR_materials_sheen), likewise (MATERIAL_SHEEN).
  const Texture* sheen = nullptr;
};

// std430 mirror of the header of `LayerLists` in shaders/lighting/layer_lists.glsl; a head per pixel (4 bytes) and
// the nodes (16 bytes each) follow it.
struct LayerListHeader {
  uint32_t nodeCount, nodeCapacity, droppedNodes, heads;
};
static_assert(sizeof(LayerListHeader) == 16, "LayerListHeader must match its std430 layout");
// Nodes per pixel of the frame that exact order-independent transparency keeps room for (16 bytes each): a frame
// whose BLEND fragments in front of the opaque surfaces outnumber them drops the rest, and says so.
constexpr uint32_t kLayerNodesPerPixel = 8;
// Fragments of one pixel the exact resolve sorts and composites, the nearest (layer_resolve.comp's MAX_LAYERS).
constexpr uint32_t kMaxLayersPerPixel = 32;

// The targets of an order-independent ordering, the frame's size; all null: BLEND surfaces are composited back to
// front instead.
// - Weighted blended (McGuire & Bavoil 2013): RGBA32F accumulation (the sums of w a C and of w a; float, as lit HDR
//   colour times weights up to 3,000 overflows fp16) and R16F revealage (the product of 1 - a).
// - Exact: the lists, LayerListHeader, then a head per pixel and kLayerNodesPerPixel nodes per pixel.
// The transmissive surfaces (BlendedSurfaces drawing BlendedSet::Transmissive into the radiance target) and the
// texture, of the radiance target's format and size with a full mip chain, that the opaque frame behind them is
// copied to before they are drawn.
struct TransmissionTargets {
  const BlendedSurfaces* surfaces = nullptr;
  const Texture* background = nullptr;
};
struct OitTargets {
  const Texture* accumulation = nullptr;
  const Texture* revealage = nullptr;
  const Buffer* layerLists = nullptr;
};
// The bytes of the exact lists for a frame of `pixels` pixels: kLayerNodesPerPixel nodes a pixel, fewer where the
// driver's largest storage block (`maxBlockBytes`) holds fewer, which the dropped count then reports. Throws
// std::runtime_error naming --transparency exact when the block cannot hold the heads and a node per pixel.
size_t layerListBytes(size_t pixels, uint64_t maxBlockBytes);
// BLEND fragments the last frame composited through `lists` left out (over the nodes' capacity, or past a pixel's
// kMaxLayersPerPixel nearest); waits for the GPU.
uint32_t readDroppedLayers(const Buffer& lists);

// List entries (or, in a cluster whose list overflowed, lights) one clustered dispatch of the lighting pass loops
// over at most: one iteration each, with room for the pass's few other loops under llvmpipe's 65535 iterations per
// invocation. More take several dispatches (LIGHT_CHUNKS). Shading every light, a dispatch takes one uniform-buffer
// window of lights.
constexpr uint32_t kLightsPerDispatch = 32768;

// The brute-force path's light window: kLightWindowMax lights, or the largest power of two of them that the
// driver's uniform blocks hold.
uint32_t lightWindowLights();

// Deferred lighting in a compute shader; one permutation per (model, variant, radiance format, culling, stats,
// IBL, spot lights present, shadow filter or none), compiled on first use.
class LightingPass {
 public:
  explicit LightingPass(ProgramCache& programs)
      : programs_(programs),
        ambientAlbedo_(programs.library()),
        sheenAlbedo_(programs.library()),
        ambientSampler_("lighting.ambientAlbedo.sampler", GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_LINEAR, GL_LINEAR),
        backgroundSampler_("lighting.transmissionBackground.sampler", GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE,
                           GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR),
        lightWindow_(lightWindowLights()) {}

  // With `clusters` null every light is shaded for every pixel: the brute-force reference path. Otherwise
  // only the lights of each pixel's cluster (as last assigned) are. `radiance` (an HdrFormat) comes in holding the
  // surfaces' emitted radiance, and black with alpha 1 where no surface is drawn (the background of a frame without
  // an environment, the G-buffer pass's clear), and leaves with the shaded frame: emission plus reflected light. Over
  // kLightsPerDispatch lights, the running sums go through `partialRadiance` (RGBA32F, the frame's size).
  void render(const SurfaceTextures& surface, const LightBuffer& lights, const LightingOptions& options,
              const UniformBuffer<FrameBlock>& frame, const Texture& radiance, const LightClusters* clusters,
              const Texture* partialRadiance);

  // The BLEND surfaces, lit as render lights the G-buffer's (the same lights, lists, models, environment and
  // shadows: shaders/lighting/forward.frag) and composited over `radiance`: back to front, drawn into it; or with
  // `oit`'s weighted targets, drawn into them (which `surfaces` draws into) and composited from them
  // (shaders/lighting/oit_composite.comp); or with its lists, each fragment kept in its pixel's list and the lists
  // composited in depth order (shaders/lighting/layer_resolve.comp). Over kLightsPerDispatch lights (or a
  // brute-force window), each object is drawn once per chunk of lights, the later chunks adding to the first.
  // Before them, with `transmission`'s surfaces, the opaque frame is copied to its background with a mip chain,
  // and the transmissive surfaces drawn back to front over `radiance`, seeing the background through them
  // (KHR_materials_transmission and _volume) and writing depth, whatever `oit` says.
  void renderBlended(const BlendedSurfaces& surfaces, const TransmissionTargets& transmission,
                     const LightBuffer& lights, const LightingOptions& options, const UniformBuffer<FrameBlock>& frame,
                     const Texture& radiance, const LightClusters* clusters, const OitTargets& oit);

  // Whether a frame of `lights` lights takes several dispatches, and so a running-sum image.
  bool needsLightChunks(uint32_t lights, bool clustered) const { return lights > lightsPerDispatch(clustered); }

  // Pair counts of the last frame rendered with stats on; waits for the GPU.
  PairCounts readPairCounts() const;

 private:
  const Program& program(const LightingOptions& options, bool clustered, unsigned radianceFormat, bool chunked,
                         LightKinds kinds);
  // Binds the frame, the lights, the lists, the environment or ambient table and the shadow maps for shading.
  void bindShading(const LightBuffer& lights, const LightingOptions& options, const UniformBuffer<FrameBlock>& frame,
                   const LightClusters* clusters);
  uint32_t lightsPerDispatch(bool clustered) const { return clustered ? kLightsPerDispatch : lightWindow_; }
  // Sorts the frame's groupsX x groupsY tiles into those holding a surface and the others (surface_tiles.comp) and
  // binds the lists for the indirect dispatches over them.
  void sortTiles(GLuint groupsX, GLuint groupsY);

  ProgramCache& programs_;  // permutations compiled on first use
  UniformBuffer<LightingBlock> block_{"lighting.block"};
  AmbientAlbedoTables ambientAlbedo_;  // PBR's response to uniform ambient light, per variant
  SheenAlbedoTable sheenAlbedo_;       // KHR_materials_sheen's albedo, made for the first scene with a sheen
  Sampler ambientSampler_;
  Sampler backgroundSampler_;  // trilinear over the transmission background's mip chain
  std::unique_ptr<Buffer> pairStats_;
  size_t pairGroups_ = 0;
  std::unique_ptr<Buffer> surfaceTiles_;  // SurfaceTilesHeader, then two lists of tile indices
  uint32_t lightWindow_;  // lights in the uniform-buffer window of the brute-force path
};

}  // namespace pbr
