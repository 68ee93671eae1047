#include "lighting/cluster_debug_pass.hpp"

#include <stdexcept>

#include "lighting/lighting_bindings.hpp"

namespace pbr {

ClusterDebugView parseClusterDebugView(const std::string& name) {
  if (name == "none") return ClusterDebugView::None;
  if (name == "clusters") return ClusterDebugView::Clusters;
  if (name == "slices") return ClusterDebugView::Slices;
  throw std::invalid_argument("unknown debug view '" + name + "' (expected clusters or slices)");
}

void ClusterDebugPass::render(ClusterDebugView view, const LightClusters& clusters, const Texture& depth,
                              const UniformBuffer<FrameBlock>& frame, const Texture& ldr) {
  if (view == ClusterDebugView::None) return;
  const bool slices = view == ClusterDebugView::Slices;
  programs_.compute("lighting/cluster_debug.comp",
                    concat({{"DEBUG_SLICES", slices ? "1" : "0"}}, lightingBindingDefines())).use();
  frame.bind(kFrameUbo.index);
  clusters.bindForLighting();
  glBindTextureUnit(lighting_binding::kDepthUnit.index, depth.id());
  glBindImageTexture(0, ldr.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((ldr.width() + 7) / 8), static_cast<GLuint>((ldr.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace pbr
