#pragma once
#include <vector>

#include <glm/vec2.hpp>

#include "core/io/frame_timing.hpp"
#include "renderer/renderer.hpp"

namespace pbr {

// Warm frames of `scene` at `size`, rendered with `config`, under each of `options`: each configuration's renderer
// is made and warmed up untimed first (its permutations compiled, its targets, such as the shadow atlas or the
// order-independent accumulation, allocated), then every round renders one frame per configuration, the
// configurations in turn (A B C A B C ...), so that a drift of a shared machine hits all alike. Per configuration,
// its rounds' timings, oldest first.
std::vector<std::vector<FrameTiming>> timeFramesInTurn(const ShaderLibrary& shaders, const Scene& scene,
                                                       glm::ivec2 size, const RendererConfig& config,
                                                       const std::vector<FrameOptions>& options, int rounds,
                                                       TimingMode timing);

}  // namespace pbr
