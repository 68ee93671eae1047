#include "app/accuracy/frames_in_turn.hpp"

#include <memory>

namespace pbr {

std::vector<std::vector<FrameTiming>> timeFramesInTurn(const ShaderLibrary& shaders, const Scene& scene,
                                                       glm::ivec2 size, const RendererConfig& config,
                                                       const std::vector<FrameOptions>& options, int rounds,
                                                       TimingMode timing) {
  std::vector<std::unique_ptr<Renderer>> renderers;
  std::vector<FrameOptions> withoutStats = options;
  for (FrameOptions& o : withoutStats) {
    o.stats = false;  // GPU counters cost time
    renderers.push_back(std::make_unique<Renderer>(shaders, scene, size.x, size.y, config));
    Profiler untimed(timing);
    renderers.back()->renderFrame(o, untimed);
    renderers.back()->warmUp(o, untimed, 2);
  }
  std::vector<std::vector<FrameTiming>> out(options.size());
  for (int round = 0; round < rounds; ++round) {
    for (size_t i = 0; i < renderers.size(); ++i) {
      Profiler profiler(timing);
      renderers[i]->renderFrame(withoutStats[i], profiler);
      out[i].push_back(profiler.takeResults(true).at(0));
    }
  }
  return out;
}

}  // namespace pbr
