#include "app/frame_settings.hpp"

#include <algorithm>

#include "app/common_options.hpp"
#include "debug/debug_channel.hpp"
#include "post/anti_aliasing.hpp"

namespace pbr {

namespace {

constexpr const char* kFrameSettings[] = {
    "--model",      "--variant",        "--visibility",    "--hdr-format",   "--gbuffer",      "--culling",
    "--tile",       "--slices",         "--assign-shape",  "--aa",           "--shadows",      "--shadow-filter",
    "--shadow-atlas", "--shadow-draws", "--shadow-cache",  "--debug",        "--tonemap",      "--transparency"};

// The record as a command line of its frame settings, each a valued option, so that Args checks their numbers.
Args recordArgs(const RenderSettings& record) {
  std::vector<OptionSpec> specs;
  std::vector<std::string> argv;
  for (const auto& [option, value] : record) {
    if (!isFrameSetting(option)) continue;
    specs.push_back({option, "V", ""});
    argv.push_back(option);
    argv.push_back(value);
  }
  return Args(specs, argv);
}

}  // namespace

bool isFrameSetting(const std::string& option) {
  return std::any_of(std::begin(kFrameSettings), std::end(kFrameSettings),
                     [&](const char* name) { return option == name; });
}

FrameSettings frameSettings(const RenderSettings& record, FrameSettings settings) {
  const Args args = recordArgs(record);
  FrameOptions& frame = settings.frame;
  RendererConfig& renderer = settings.renderer;
  if (args.has("--model")) frame.model = parseShadingModel(args.get("--model"));
  if (args.has("--variant")) {
    std::vector<std::string> keys;
    frame.variant = parseShadingVariant(args.get("--variant"), &keys);
    // A term of the other model, or one chosen twice, would be dropped without a word.
    for (const std::string& key : keys) {
      if ((key == "lobe") != (frame.model == ShadingModel::BlinnPhong)) {
        throw UsageError("--variant " + args.get("--variant") + ": " + key + " is a term of the " +
                         (key == "lobe" ? "blinn-phong" : "pbr") + " model, not of --model " + toString(frame.model));
      }
    }
    if (args.has("--visibility") && std::find(keys.begin(), keys.end(), "visibility") != keys.end()) {
      throw UsageError("--visibility and --variant " + args.get("--variant") + " both choose the visibility term");
    }
  }
  if (args.has("--visibility")) {
    if (frame.model != ShadingModel::Pbr) {
      throw UsageError("--visibility is a term of the pbr model, not of --model " + std::string(toString(frame.model)));
    }
    frame.variant.visibility = parseVisibility(args.get("--visibility"));
  }
  if (args.has("--hdr-format")) renderer.hdrFormat = parseHdrFormat(args.get("--hdr-format"));
  if (args.has("--gbuffer")) renderer.gbuffer = parseGBufferPrecision(args.get("--gbuffer"));
  if (args.has("--culling")) frame.culling = parseCulling(args.get("--culling"));
  ClusterConfig& clusters = renderer.clusters;
  if (args.has("--tile") && args.get("--tile") != "auto") {
    clusters.tileTrial = false;
    clusters.tileSize = args.getInt("--tile", 8, 512);
  }
  if (args.has("--slices")) clusters.slices = args.getInt("--slices", 1, 256);
  if (args.has("--assign-shape")) {
    // The cluster shape is the light pass's; its lists are filled a workgroup per list.
    clusters.lightPass = clusters.fill = parseAssignShape(args.get("--assign-shape"));
    if (clusters.fill == AssignShape::Cluster) clusters.fill = AssignShape::Workgroup;
  }
  if (args.has("--aa")) frame.aa = parseAntiAliasing(args.get("--aa"));
  if (args.has("--shadows")) frame.shadows.mode = parseShadowMode(args.get("--shadows"));
  if (args.has("--shadow-filter")) frame.shadows.filter = parseShadowFilter(args.get("--shadow-filter"));
  if (args.has("--shadow-atlas")) frame.shadows.atlasSize = readShadowAtlas(args);
  if (args.has("--shadow-draws")) frame.shadows.draws = parseShadowDraws(args.get("--shadow-draws"));
  if (args.has("--shadow-cache")) frame.shadows.cache = readShadowCache(args);
  if (args.has("--debug")) {
    frame.debug = parseDebugChannel(args.get("--debug"));
    // The cluster views show the grid that only clustered culling builds; efficiency is measured either way.
    if (needsClusterGrid(*frame.debug) && frame.culling == Culling::None) {
      throw UsageError(std::string("--debug ") + toString(*frame.debug) + " needs --culling clustered");
    }
  }
  if (args.has("--tonemap")) frame.toneCurve = readToneCurve(args);
  if (args.has("--transparency")) frame.transparency = readTransparency(args);
  return settings;
}

}  // namespace pbr
