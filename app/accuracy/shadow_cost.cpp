#include "app/accuracy/shadow_cost.hpp"

#include <memory>

namespace pbr {

std::vector<ShadowCost> measureShadowCost(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                                          const RendererConfig& config, const std::vector<FrameOptions>& options,
                                          int rounds, TimingMode timing) {
  struct Run {
    std::unique_ptr<Renderer> renderer;
    FrameOptions options;
    std::vector<double> shadow, lighting, passes;
  };
  std::vector<Run> runs;
  for (const FrameOptions& o : options) {
    Run run{std::make_unique<Renderer>(shaders, scene, size.x, size.y, config), o, {}, {}, {}};
    run.options.stats = false;
    Profiler untimed(timing);
    run.renderer->renderFrame(run.options, untimed);
    run.renderer->warmUp(run.options, untimed, 2);  // compiles the permutation and allocates the atlas untimed
    runs.push_back(std::move(run));
  }
  for (int round = 0; round < rounds; ++round) {
    for (Run& run : runs) {
      Profiler profiler(timing);
      run.renderer->renderFrame(run.options, profiler);
      const FrameTiming f = profiler.takeResults(true).at(0);
      run.shadow.push_back(f.pass("shadow"));
      run.lighting.push_back(f.pass("lighting"));
      run.passes.push_back(f.pass("shadow") + f.pass("lighting"));
    }
  }
  std::vector<ShadowCost> out;
  for (const Run& run : runs)
    out.push_back({summarizeTimes(run.shadow), summarizeTimes(run.lighting), summarizeTimes(run.passes)});
  return out;
}

}  // namespace pbr
