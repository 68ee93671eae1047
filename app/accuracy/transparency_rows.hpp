#pragma once
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/accuracy/accuracy_metrics.hpp"
#include "app/accuracy/reference_comparison.hpp"
#include "app/bench/bench_sweep.hpp"
#include "core/scene/transparency.hpp"
#include "renderer/renderer.hpp"

namespace pbr {

// An ordering of BLEND surfaces `pbr accuracy` measures on a scene that has them: the exact PBR variant (the
// reference's model, as for the shadow rows) and no shadows, in the GPU frame as in the reference frame, so that how
// the layers are composited is what differs from the reference's exact per-ray compositing.
struct TransparencyRow {
  std::string name;  // "transparency-sorted", "transparency-oit"
  Transparency transparency = Transparency::Sorted;
};

// The rows measured unless --transparency-rows says otherwise.
extern const char* const kDefaultTransparencyRows;
// Comma-separated orderings (sorted, oit, exact), or "none" for no rows; throws std::invalid_argument naming the bad item.
std::vector<TransparencyRow> parseTransparencyRows(const std::string& list);

// A row's frame options: the exact variant's (exactVariantOptions), no shadows, the row's ordering; rendered with
// exactVariantConfig().
FrameOptions transparencyRowOptions(const TransparencyRow& row, const Scene& scene);

struct TransparencyRowResult {
  ErrorMetrics error;                // the frame against the reference's exactly composited one
  std::vector<float> relativeError;  // per pixel, for the error map
};

// The scene's reference frame, without shadows, made once; each row's frame against it.
class TransparencyComparison {
 public:
  TransparencyComparison(const ShaderLibrary& shaders, const Scene& scene, glm::ivec2 size,
                         const reference::ReferenceOptions& referenceOptions, TimingMode timing,
                         ToneCurve curve = ToneCurve::AcesHill);
  TransparencyRowResult measure(const TransparencyRow& row) const;

 private:
  ReferenceComparison frame_;  // against the reference without shadows
};

// What an ordering costs, in ms.
struct TransparencyCost {
  TimeSummary transparencyMs;  // the transparency pass: the draws, and for oit its targets' clear and the composite
  TimeSummary frameMs;         // the whole frame, first pass start to last pass end
};

// Times `scene` at `size` under each row, warm frames, the rows in turn (timeFramesInTurn), `rounds` frames each.
std::vector<TransparencyCost> measureTransparencyCost(const ShaderLibrary& shaders, const Scene& scene,
                                                      glm::ivec2 size, const std::vector<TransparencyRow>& rows,
                                                      int rounds, TimingMode timing);

}  // namespace pbr
