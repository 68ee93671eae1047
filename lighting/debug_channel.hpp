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

const char* toString(DebugChannel channel);  // "basecolor", "normal", ...: the name --debug takes
// Throws std::invalid_argument naming `name` and every valid name.
DebugChannel parseDebugChannel(const std::string& name);
// The names joined by `separator`: "basecolor|normal|...|efficiency" for help text.
std::string debugChannelNames(const std::string& separator = "|");

// Clusters and slices draw the cluster grid, which only clustered culling builds.
bool needsClusterGrid(DebugChannel channel);

}  // namespace pbr
