#include "debug/debug_channel.hpp"

#include <iterator>
#include <stdexcept>

namespace pbr {

namespace {

using S = DebugSource;
using N = DebugNeeds;

constexpr DebugChannelInfo kChannels[] = {
    {DebugChannel::BaseColor, "basecolor", S::Surface, N::Nothing, true, "GBUFFER_CHANNEL_BASE_COLOR"},
    {DebugChannel::Normal, "normal", S::Surface, N::Nothing, true, "GBUFFER_CHANNEL_NORMAL"},
    {DebugChannel::Roughness, "roughness", S::Surface, N::Nothing, true, "GBUFFER_CHANNEL_ROUGHNESS"},
    {DebugChannel::Metalness, "metalness", S::Surface, N::Nothing, true, "GBUFFER_CHANNEL_METALNESS"},
    {DebugChannel::Occlusion, "occlusion", S::Surface, N::Nothing, true, "GBUFFER_CHANNEL_OCCLUSION"},
    {DebugChannel::Emission, "emission", S::Emission, N::Nothing, false, "GBUFFER_CHANNEL_EMISSION"},
    {DebugChannel::Depth, "depth", S::Surface, N::Nothing, true, "GBUFFER_CHANNEL_DEPTH"},
    {DebugChannel::Clusters, "clusters", S::ClusterGrid, N::ClusterGrid, false, nullptr},
    {DebugChannel::Slices, "slices", S::ClusterGrid, N::ClusterGrid, false, nullptr},
    {DebugChannel::Efficiency, "efficiency", S::PairCounts, N::Nothing, true, nullptr},
    {DebugChannel::Shadows, "shadows", S::ShadowLight, N::ShadowCaster, true, nullptr},
    {DebugChannel::Transparency, "transparency", S::Layers, N::BlendSurface, true, nullptr},
};
static_assert(std::size(kChannels) == kDebugChannels.size(), "one row per channel");

}  // namespace

const DebugChannelInfo& debugChannelInfo(DebugChannel channel) {
  for (const DebugChannelInfo& info : kChannels) {
    if (info.channel == channel) return info;
  }
  throw std::logic_error("debug channel without a row");
}

const char* toString(DebugChannel channel) { return debugChannelInfo(channel).name; }

DebugChannel parseDebugChannel(const std::string& name) {
  for (const DebugChannel channel : kDebugChannels) {
    if (name == toString(channel)) return channel;
  }
  throw std::invalid_argument("unknown debug channel '" + name + "' (expected " + debugChannelNames(", ") + ")");
}

std::string debugChannelNames(const std::string& separator) {
  std::string names;
  for (const DebugChannel channel : kDebugChannels) names += (names.empty() ? "" : separator) + toString(channel);
  return names;
}

bool needsClusterGrid(DebugChannel channel) { return debugChannelInfo(channel).needs == DebugNeeds::ClusterGrid; }

bool isGBufferChannel(DebugChannel channel) { return debugChannelInfo(channel).gbufferDefine != nullptr; }

}  // namespace pbr
