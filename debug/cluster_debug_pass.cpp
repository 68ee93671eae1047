#include "debug/cluster_debug_pass.hpp"

#include <stdexcept>
#include <string>

#include "lighting/lighting_bindings.hpp"

namespace pbr {

void ClusterDebugPass::render(DebugChannel channel, const LightClusters& clusters, const Texture& depth,
                              const UniformBuffer<FrameBlock>& frame, const UniformBuffer<LegendBlock>& legend,
                              const Texture& ldr) {
  if (!needsClusterGrid(channel)) {
    throw std::logic_error(std::string("the cluster debug pass does not draw ") + toString(channel));
  }
  const bool slices = channel == DebugChannel::Slices;
  programs_.compute("lighting/cluster_debug.comp",
                    concat({{"DEBUG_SLICES", slices ? "1" : "0"}}, lightingBindingDefines())).use();
  frame.bind(kFrameUbo.index);
  legend.bind(lighting_binding::kLegendUbo.index);
  clusters.bindForLighting();
  glBindTextureUnit(lighting_binding::kDepthUnit.index, depth.id());
  glBindImageTexture(0, ldr.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((ldr.width() + 7) / 8), static_cast<GLuint>((ldr.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace pbr
