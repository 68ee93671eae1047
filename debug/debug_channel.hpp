#pragma once
#include <array>
#include <string>

namespace pbr {

// What a debug image shows in place of the final frame, the same set for `pbr render --debug` and the viewer's V key:
// the surface as the lighting pass reads it (base colour to depth), the emitted radiance the geometry pass writes,
// the cluster grid (lights per cluster, depth slices), the culling efficiency per pixel, the shadows (each pixel's
// visibility, with the shadow atlas inset) and the transparent layers (BLEND surfaces per pixel). Each has a legend.
enum class DebugChannel {
  BaseColor,
  Normal,
  Roughness,
  Metalness,
  Occlusion,
  Emission,
  Depth,
  Clusters,
  Slices,
  Efficiency,
  Shadows,
  Transparency,
};

// Every channel, in the order the viewer steps through them and help text lists them.
constexpr std::array<DebugChannel, 12> kDebugChannels = {
    DebugChannel::BaseColor, DebugChannel::Normal,     DebugChannel::Roughness, DebugChannel::Metalness,
    DebugChannel::Occlusion, DebugChannel::Emission,   DebugChannel::Depth,     DebugChannel::Clusters,
    DebugChannel::Slices,    DebugChannel::Efficiency, DebugChannel::Shadows,   DebugChannel::Transparency};

// What a channel draws from: the G-buffer's surface, the emitted radiance as post shows it, the cluster grid, the
// light-pixel pair counts or the casting light's visibility the lighting pass writes for it, or the BLEND layers
// it counts itself.
enum class DebugSource { Surface, Emission, ClusterGrid, PairCounts, ShadowLight, Layers };
// What the scene or frame must have for the channel to show anything (else the frame is shown as it is).
enum class DebugNeeds { Nothing, ClusterGrid, ShadowCaster, BlendSurface };

// One row per channel: the one place a channel is declared. The renderer's pass list, `render --debug` and the
// viewer read it.
struct DebugChannelInfo {
  DebugChannel channel;
  const char* name;  // what --debug takes
  DebugSource source;
  DebugNeeds needs;
  // Writes every display pixel: the passes whose output it would hide (lighting, transparency, exposure, post,
  // anti-aliasing) are left out. The emission channel keeps post (it shows post's picture of the emission) and the
  // cluster views are painted over the anti-aliased frame.
  bool replacesDisplay;
  const char* gbufferDefine;  // the define choosing it in lighting/gbuffer_debug.comp; null unless drawn there
};
const DebugChannelInfo& debugChannelInfo(DebugChannel channel);

const char* toString(DebugChannel channel);  // "basecolor", "normal", ...: the name --debug takes
// Throws std::invalid_argument naming `name` and every valid name.
DebugChannel parseDebugChannel(const std::string& name);
// The names joined by `separator`: "basecolor|normal|...|efficiency" for help text.
std::string debugChannelNames(const std::string& separator = "|");

// Clusters and slices draw the cluster grid, which only clustered culling builds.
bool needsClusterGrid(DebugChannel channel);
// Whether GBufferDebugPass draws the channel (it has a gbufferDefine): the surface's channels and the emission the
// geometry pass writes.
bool isGBufferChannel(DebugChannel channel);

}  // namespace pbr
