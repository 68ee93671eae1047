#include "lighting/debug_channel.hpp"

#include <stdexcept>

namespace pbr {

const char* toString(DebugChannel channel) {
  switch (channel) {
    case DebugChannel::BaseColor: return "basecolor";
    case DebugChannel::Normal: return "normal";
    case DebugChannel::Roughness: return "roughness";
    case DebugChannel::Metalness: return "metalness";
    case DebugChannel::Occlusion: return "occlusion";
    case DebugChannel::Emission: return "emission";
    case DebugChannel::Depth: return "depth";
    case DebugChannel::Clusters: return "clusters";
    case DebugChannel::Slices: return "slices";
    case DebugChannel::Efficiency: return "efficiency";
    case DebugChannel::Shadows: return "shadows";
    case DebugChannel::Transparency: return "transparency";
  }
  return "?";
}

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

bool needsClusterGrid(DebugChannel channel) {
  return channel == DebugChannel::Clusters || channel == DebugChannel::Slices;
}

}  // namespace pbr
