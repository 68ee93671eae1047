#pragma once
#include <functional>
#include <vector>

#include "app/accuracy/pair_cost_settings.hpp"
#include "core/gl/shader_library.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

// The fixture: a matte-to-glossy dielectric floor seen from above, filling a 16:9 frame, under a BLEND pane (alpha
// 0.5) filling it too, and `lights` seeded lights in a layer above both with radii far larger than the scene. The
// lighting pass shades the floor's pairs, the transparency pass the pane's: the same pixels and lights.
Scene pairCostScene(int lights, FixtureMaterial material = FixtureMaterial::Core);

// Times every variant's lighting and transparency passes `rounds` times, visiting the variants in turn (A B C A B C
// ...) so that a drift of a shared machine hits all alike; each round also times the pass with no lights for
// fixedShare. On the fixture (`scene` null) every pixel evaluates every light; on a scene the pairs are those its
// frame evaluates with the variant's culling, counted on the GPU once warm. `progress` is called with (timed frames
// done, total).
std::vector<PairCost> measurePairCost(const ShaderLibrary& shaders, const std::vector<PairCostVariant>& variants,
                                      const PairCostSettings& settings, const Scene* scene = nullptr,
                                      const std::function<void(int, int)>& progress = {});

}  // namespace pbr
