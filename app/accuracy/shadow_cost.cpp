#include "app/accuracy/shadow_cost.hpp"

#include "app/accuracy/frames_in_turn.hpp"

namespace pbr {

std::vector<ShadowCost> measureShadowCost(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                                          const RendererConfig& config, const std::vector<FrameOptions>& options,
                                          int rounds, TimingMode timing) {
  std::vector<ShadowCost> out;
  for (const std::vector<FrameTiming>& frames :
       timeFramesInTurn(shaders, scene, size, config, options, rounds, timing)) {
    std::vector<double> shadow, lighting, passes;
    for (const FrameTiming& f : frames) {
      shadow.push_back(f.pass("shadow"));
      lighting.push_back(f.pass("lighting"));
      passes.push_back(f.pass("shadow") + f.pass("lighting"));
    }
    out.push_back({summarizeTimes(shadow), summarizeTimes(lighting), summarizeTimes(passes)});
  }
  return out;
}

}  // namespace pbr
