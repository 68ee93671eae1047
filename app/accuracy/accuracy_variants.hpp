#pragma once
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/accuracy/pair_cost_settings.hpp"
#include "app/frame_settings.hpp"
#include "app/render_settings.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/shading_model.hpp"
#include "gbuffer/gbuffer_precision.hpp"
#include "renderer/frame_options.hpp"
#include "renderer/renderer_config.hpp"

namespace pbr {

// One rung of the speed/accuracy ladder: a name and the settings it renders with, as pbr render's options take
// them (`record`: the model, its terms, the precision of the HDR target and the G-buffer), and what they decide
// over the renderer's defaults (`settings`).
struct AccuracyVariant {
  AccuracyVariant(std::string name_, RenderSettings record_);
  std::string name;
  RenderSettings record;
  FrameSettings settings;
  ShadingModel model() const { return settings.frame.model; }
  const ShadingVariant& shading() const { return settings.frame.variant; }
  HdrFormat hdr() const { return settings.renderer.hdrFormat; }
  GBufferPrecision gbuffer() const { return settings.renderer.gbuffer; }
};

// The variant as the per-pair cost measurement takes it.
PairCostVariant pairCostVariant(const AccuracyVariant& v);

// Every variant `pbr accuracy` knows, the reference-equivalent one ("exact") first.
const std::vector<AccuracyVariant>& accuracyLadder();
// A comma-separated list of ladder names, or "all"; throws std::invalid_argument for an unknown name.
std::vector<AccuracyVariant> selectVariants(const std::string& names);

// The rows that measure a setting other than the shading (shadow rows, transparency rows) render with the ladder's
// first variant, "exact", the reference's model, so that the setting is what differs from the reference: its
// renderer configuration (HDR target, G-buffer), and its frame options (model, terms) at the scene's exposure.
const AccuracyVariant& exactVariant();
RendererConfig exactVariantConfig();
FrameOptions exactVariantOptions(const Scene& scene);

// A comma-separated list of rows, each read by `parseItem` (which throws std::invalid_argument naming a bad item),
// or "none" for no rows; an empty list is refused, naming the `kind` of row.
template <class Row>
std::vector<Row> parseRowList(const std::string& list, const std::string& kind,
                              const std::function<Row(const std::string&)>& parseItem) {
  std::vector<Row> rows;
  if (list == "none") return rows;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) rows.push_back(parseItem(item));
  if (rows.empty()) throw std::invalid_argument("no " + kind + " row listed (none for no rows)");
  return rows;
}

struct AccuracyScene {
  std::string label;  // file-name safe: fresnel-floor:40 becomes fresnel-floor-40
  Scene scene;
};
// True when every object is a plane, sphere or box: the reference can then also ray-cast the exact shapes.
bool hasOnlyAnalyticShapes(const Scene& scene);

// A built-in scene name or file, or "fresnel-floor:DEG" for that view angle, loaded with `params` (the view angle
// set from the spec, and no default environment, which the reference could not render). The reference ignores
// textures, so base colour textures are removed.
AccuracyScene loadAccuracyScene(const std::string& spec, SceneParams params = {});

}  // namespace pbr
