#pragma once
#include <memory>

#include "core/gl/gl_objects.hpp"
#include "core/gl/program_cache.hpp"
#include "gbuffer/gbuffer.hpp"
#include "lighting/light_clusters.hpp"
#include "renderer/renderer_config.hpp"

namespace pbr {

// What lives as long as the frame size: the HDR radiance target, the G-buffer drawn around it, the final RGBA8
// frame and the cluster grid with its light lists. A resize replaces this and nothing else; its programs come
// from the scene's cache, compiled already. The G-buffer has the channels of the scene's `layout`; a scene with
// transmissive materials (`transmission`) has the copy of the opaque frame they see through counted in the size
// check, though it is made on first use.
struct FrameTargets {
  // Throws std::runtime_error naming config.sizeOption when the frame is over the context's texture size, the
  // memory available or what the driver can create (renderer/frame_limits.hpp), before any target is allocated.
  FrameTargets(ProgramCache& programs, int width, int height, const RendererConfig& config,
               const GBufferLayout& layout, bool transmission);

  int width, height;
  Texture hdr;  // radiance: emission from the G-buffer pass, then reflected light from the lighting pass
  GBuffer gbuffer;
  Texture ldr;  // the final RGBA8 frame, rows bottom-up as GL stores them
  LightClusters clusters;
  // The radiance target over the G-buffer's depth: BLEND surfaces are drawn into it, in front of the opaque ones.
  Framebuffer blendTarget;

  // RGBA32F running sums of the lighting pass when it needs several dispatches (over kLightsPerDispatch lights):
  // made on first use, as only such frames need its 16 bytes per pixel.
  const Texture& partialRadiance();
  // The opaque frame that transmissive surfaces see through (TransmissionTargets): the radiance target's format
  // with a full mip chain, 4/3 of its bytes, made on first use.
  const Texture& transmissionBackground();
  // The tone-mapped RGBA8 frame before anti-aliasing, which writes `ldr`: made on first use.
  const Texture& beforeAntiAliasing();
  // RG32UI light-pixel pairs of each pixel (evaluated, contributing) for the efficiency debug view: made on first use.
  const Texture& pairCounts();
  // RG32F luminance from casting lights (with shadows, without) for the shadows debug view: made on first use.
  const Texture& shadowLight();
  // Order-independent transparency's targets over the G-buffer's depth (LightingPass::renderBlended): RGBA32F
  // accumulation and R16F revealage, 18 bytes per pixel made on first use.
  struct OrderIndependent {
    Texture accumulation, revealage;
    Framebuffer framebuffer;
  };
  const OrderIndependent& orderIndependent();
  // Exact order-independent transparency's lists (LightingPass::renderBlended): a head and kLayerNodesPerPixel
  // nodes per pixel, 132 bytes per pixel made on first use.
  const Buffer& layerLists();
  // The lists if a frame of this size has made them (a resize drops them with the other targets).
  const Buffer* layerListsIfMade() const { return layerLists_.get(); }
  // R32F BLEND layers per pixel over the G-buffer's depth, for the transparency debug view: made on first use.
  struct LayerCount {
    Texture layers;
    Framebuffer framebuffer;
  };
  const LayerCount& layerCount();

 private:
  std::unique_ptr<Texture> partialRadiance_, transmissionBackground_, beforeAntiAliasing_, pairCounts_, shadowLight_;
  std::unique_ptr<OrderIndependent> orderIndependent_;
  std::unique_ptr<LayerCount> layerCount_;
  std::unique_ptr<Buffer> layerLists_;
};

}  // namespace pbr
