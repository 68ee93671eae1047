#pragma once
#include <cstdint>
#include <string>

#include <glm/vec2.hpp>

#include "app/bench/bench_sweep.hpp"
#include "core/io/frame_timing.hpp"
#include "renderer/frame_options.hpp"
#include "renderer/renderer_config.hpp"

namespace pbr {

// The cost of one evaluated light-pixel pair of a shading variant's lighting pass, measured where that cost
// dominates: brute force (every light for every pixel), a floor filling the whole frame, and lights whose
// spheres reach every pixel from above, so that every pair runs the whole BRDF (no early-out is taken).
struct PairCostSettings {
  glm::ivec2 size{1280, 720};
  std::string sizeOption = "--size";  // named when the size is too large: bench's --size, accuracy's --pair-size
  // 128 keeps the pass with no lights near a tenth of the pass with them (measured, PBR on llvmpipe).
  int lights = 128;
  int rounds = 7;  // each round times every variant once, in turn
  TimingMode timing = TimingMode::Serializing;
  // Empty: the fixture. Else the scene measured instead (`--pair-scene`), as users' frames pay for their pairs:
  // its lights reach what they reach, and each variant is timed brute force and clustered, per evaluated pair.
  std::string scene;
};

// The material of the fixture's surfaces: the core metal-rough material, or it with one glTF extension's lobe
// (ior 1.33 with a tinted specular colour, a clear coat of roughness 0.1, a sheen of roughness 0.5), whose per-pair
// cost is then what the lobe adds.
enum class FixtureMaterial { Core, Specular, Clearcoat, Sheen };
FixtureMaterial parseFixtureMaterial(const std::string& name);  // "core", "specular", "clearcoat", "sheen"
const char* toString(FixtureMaterial material);

struct PairCostVariant {
  std::string name;
  FrameOptions options;  // model and variant; culling is forced to none
  RendererConfig config;
  FixtureMaterial material = FixtureMaterial::Core;
  Culling culling = Culling::None;  // the fixture's pairs are all evaluated either way: brute force there
};

struct PairCost {
  std::string name;
  FixtureMaterial material = FixtureMaterial::Core;
  Culling culling = Culling::None;
  TimeSummary nsPerPair;  // ns per evaluated light-pixel pair (the summary's fields, in ns, not ms)
  // Median lighting pass with no lights over the median with `lights`: the share of per-pixel work that is not
  // per pair (reading the G-buffer, ambient, the store), which the ratio includes.
  double fixedShare = 0.0;
  uint64_t pairs = 0;  // evaluated per frame
  // The same for the transparency pass's pairs (forward lighting of the fixture's BLEND pane, every pixel too);
  // measured on the fixture only (PairCostSettings::scene empty), zero on a scene.
  TimeSummary transparentNsPerPair;
  double transparentFixedShare = 0.0;
};

}  // namespace pbr
