#pragma once
#include <vector>

#include <glm/vec2.hpp>

#include "app/bench/bench_sweep.hpp"
#include "renderer/renderer.hpp"

namespace pbr {

// What a shadow setting costs a frame, in ms: the passes it adds to or changes, the shadow maps' rendering and the
// lighting pass that looks them up and filters them.
struct ShadowCost {
  TimeSummary shadowMs;    // the shadow pass; 0 where no light casts (no pass runs)
  TimeSummary lightingMs;  // the lighting pass
  TimeSummary passesMs;    // the two together, frame by frame
};

// Times `scene` at `size` under each of `options` (rendered with `config`), one warm frame per configuration and
// round, visiting the configurations in turn (A B C A B C ...) so that a drift of a shared machine hits all alike.
std::vector<ShadowCost> measureShadowCost(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                                          const RendererConfig& config, const std::vector<FrameOptions>& options,
                                          int rounds, TimingMode timing);

}  // namespace pbr
