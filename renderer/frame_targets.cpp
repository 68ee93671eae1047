#include "renderer/frame_targets.hpp"

#include <algorithm>

#include "core/gl/hdr_format.hpp"
#include "lighting/lighting_pass.hpp"
#include "renderer/driver_limits.hpp"

namespace pbr {

namespace {

// Called while `width` is initialised, before any member allocates a target: an impossible size fails here.
int checkedWidth(int width, int height, const RendererConfig& config, const GBufferLayout& layout,
                 bool transmission) {
  checkFrameSize(width, height, config.sizeOption, frameBytesPerPixel(config, layout, transmission),
                 queryFrameLimits());
  checkFrameFormats(width, height, config.sizeOption, frameFormats(config, layout));
  return width;
}

}  // namespace

FrameTargets::FrameTargets(ProgramCache& programs, int w, int h, const RendererConfig& config,
                           const GBufferLayout& layout, bool transmission)
    : width(checkedWidth(w, h, config, layout, transmission)),
      height(h),
      hdr("frame.radiance", glInternalFormat(config.hdrFormat), w, h),
      gbuffer(w, h, hdr, config.gbuffer, layout),
      ldr("frame.display", GL_RGBA8, w, h),
      clusters(programs, config.clusters),
      blendTarget("frame.blendTarget") {
  blendTarget.attach(GL_COLOR_ATTACHMENT0, hdr);
  blendTarget.attach(GL_DEPTH_ATTACHMENT, gbuffer.depth);
  blendTarget.checkComplete();
}

const Texture& FrameTargets::partialRadiance() {
  if (!partialRadiance_) {
    partialRadiance_ = std::make_unique<Texture>("frame.partialRadiance", GL_RGBA32F, width, height);
  }
  return *partialRadiance_;
}

const Texture& FrameTargets::transmissionBackground() {
  if (!transmissionBackground_) {
    int levels = 1;
    while ((std::max(width, height) >> levels) > 0) ++levels;
    transmissionBackground_ =
        std::make_unique<Texture>("frame.transmissionBackground", hdr.format(), width, height, levels);
  }
  return *transmissionBackground_;
}

const Texture& FrameTargets::beforeAntiAliasing() {
  if (!beforeAntiAliasing_) {
    beforeAntiAliasing_ = std::make_unique<Texture>("frame.beforeAntiAliasing", GL_RGBA8, width, height);
  }
  return *beforeAntiAliasing_;
}

const Texture& FrameTargets::shadowLight() {
  if (!shadowLight_) shadowLight_ = std::make_unique<Texture>("frame.shadowLight", GL_RG32F, width, height);
  return *shadowLight_;
}

const Texture& FrameTargets::pairCounts() {
  if (!pairCounts_) pairCounts_ = std::make_unique<Texture>("frame.pairCounts", GL_RG32UI, width, height);
  return *pairCounts_;
}

const FrameTargets::OrderIndependent& FrameTargets::orderIndependent() {
  if (!orderIndependent_) {
    orderIndependent_.reset(new OrderIndependent{Texture("frame.oitAccumulation", GL_RGBA32F, width, height),
                                                 Texture("frame.oitRevealage", GL_R16F, width, height),
                                                 Framebuffer("frame.oitTarget")});
    OrderIndependent& o = *orderIndependent_;
    o.framebuffer.attach(GL_COLOR_ATTACHMENT0, o.accumulation);
    o.framebuffer.attach(GL_COLOR_ATTACHMENT1, o.revealage);
    o.framebuffer.attach(GL_DEPTH_ATTACHMENT, gbuffer.depth);
    const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(o.framebuffer.id(), 2, drawBuffers);
    o.framebuffer.checkComplete();
  }
  return *orderIndependent_;
}

const FrameTargets::LayerCount& FrameTargets::layerCount() {
  if (!layerCount_) {
    layerCount_.reset(new LayerCount{Texture("frame.layerCount", GL_R32F, width, height),
                                     Framebuffer("frame.layerCountTarget")});
    layerCount_->framebuffer.attach(GL_COLOR_ATTACHMENT0, layerCount_->layers);
    layerCount_->framebuffer.attach(GL_DEPTH_ATTACHMENT, gbuffer.depth);
    layerCount_->framebuffer.checkComplete();
  }
  return *layerCount_;
}

const Buffer& FrameTargets::layerLists() {
  if (!layerLists_) {
    GLint64 maxBlock = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
    layerLists_ = std::make_unique<Buffer>("frame.layerLists",
                                           layerListBytes(size_t(width) * size_t(height), uint64_t(maxBlock)));
  }
  return *layerLists_;
}

}  // namespace pbr
