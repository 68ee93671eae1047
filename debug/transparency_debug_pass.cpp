#include "debug/transparency_debug_pass.hpp"

#include <string>
#include <vector>

#include "lighting/blended_programs.hpp"
#include "lighting/lighting_bindings.hpp"

namespace pbr {

void TransparencyDebugPass::render(const BlendedSurfaces& surfaces, const Texture& layers,
                                   const UniformBuffer<FrameBlock>& frame, const UniformBuffer<LegendBlock>& legend,
                                   const Texture& ldr) {
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(layers.id(), 0, GL_RGBA, GL_FLOAT, zero);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  // Every face the transparency pass composites is a layer: both faces of a double-sided surface count.
  BlendedPrograms programs(programs_, "lighting/layer_count.frag", [](const std::vector<BindingPoint>& bindings) {
    std::vector<BindingPoint> points = {kFrameUbo};
    points.insert(points.end(), bindings.begin(), bindings.end());
    return bindingDefines(points);
  });
  surfaces.draw(
      [&](int, const std::string& vertexShader, const ShaderDefines& material,
          const std::vector<BindingPoint>& bindings) -> const Program& {
        return programs.get(vertexShader, material, bindings);
      },
      BlendOrder::Any, 1, BlendedSet::Blend);
  glDisable(GL_BLEND);

  programs_.compute("lighting/transparency_debug.comp",
                    concat({{"MAX_SHOWN_LAYERS", std::to_string(kMaxShownLayers)}}, lightingBindingDefines()))
      .use();
  frame.bind(kFrameUbo.index);
  legend.bind(lighting_binding::kLegendUbo.index);
  glBindTextureUnit(lighting_binding::kOitAccumulationUnit.index, layers.id());
  glBindImageTexture(0, ldr.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  glDispatchCompute(static_cast<GLuint>((ldr.width() + 7) / 8), static_cast<GLuint>((ldr.height() + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

}  // namespace pbr
