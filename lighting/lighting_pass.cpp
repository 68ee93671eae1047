#include "lighting/lighting_pass.hpp"

#include "core/bindings.hpp"

namespace pbr {

const Program& LightingPass::program(const LightingOptions& o) {
  const bool blinnPhong = o.model == ShadingModel::BlinnPhong;
  const bool fast = !blinnPhong && o.visibility == Visibility::Hammon;
  const int key = (blinnPhong ? 1 : 0) | (fast ? 2 : 0);
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    const ShaderDefines defines = {{"SHADING_MODEL_BLINN_PHONG", blinnPhong ? "1" : "0"},
                                   {"VISIBILITY_FAST", fast ? "1" : "0"}};
    it = programs_.emplace(key, shaders_.compute("lighting/deferred.comp", defines)).first;
  }
  return it->second;
}

void LightingPass::renderBruteForce(const SurfaceTextures& surface, const LightBuffer& lights,
                                    const LightingOptions& options, const UniformBuffer<FrameBlock>& frame,
                                    const Texture& hdrOut) {
  block_.update({glm::vec4(options.ambient, 0.0f), glm::uvec4(lights.count(), 0, 0, 0)});
  program(options).use();
  frame.bind(binding::kFrameUbo);
  block_.bind(binding::kLightingUbo);
  lights.bind();
  const GLuint textures[] = {surface.baseColor.id(), surface.normal.id(), surface.material.id(), surface.depth.id()};
  glBindTextures(0, 4, textures);
  glBindImageTexture(0, hdrOut.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((hdrOut.width() + 7) / 8), static_cast<GLuint>((hdrOut.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace pbr
