#include "renderer/pass_list.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace pbr {

namespace {

bool isFrameInput(FrameResource r) {
  return r == FrameResource::Geometry || r == FrameResource::Lights || r == FrameResource::Environment ||
         r == FrameResource::Camera;
}

std::string joined(const std::vector<FrameResource>& resources) {
  std::string out;
  for (const FrameResource r : resources) out += (out.empty() ? "" : ", ") + std::string(toString(r));
  return out.empty() ? "nothing" : out;
}

}  // namespace

const char* toString(FrameResource resource) {
  switch (resource) {
    case FrameResource::Geometry: return "geometry";
    case FrameResource::Lights: return "lights";
    case FrameResource::Environment: return "environment";
    case FrameResource::Camera: return "camera";
    case FrameResource::GBuffer: return "gbuffer";
    case FrameResource::ShadowMaps: return "shadow maps";
    case FrameResource::Radiance: return "radiance";
    case FrameResource::ClusterLists: return "cluster lists";
    case FrameResource::PairCounts: return "pair counts";
    case FrameResource::ShadowLight: return "shadow light";
    case FrameResource::Exposure: return "exposure";
    case FrameResource::Display: return "display";
    case FrameResource::Capture: return "capture";
  }
  return "?";
}

void checkPassList(const PassList& passes) {
  std::set<FrameResource> written;
  for (const FramePass& pass : passes) {
    for (const FrameResource r : pass.reads) {
      if (!isFrameInput(r) && !written.count(r)) {
        throw std::logic_error("pass list: '" + pass.name + "' reads " + toString(r) + ", which no earlier pass writes");
      }
    }
    written.insert(pass.writes.begin(), pass.writes.end());
  }
}

std::string describePassList(const PassList& passes) {
  std::string out;
  for (const FramePass& pass : passes) {
    out += (out.empty() ? "" : " -> ") + pass.name + " (reads " + joined(pass.reads) + "; writes " +
           joined(pass.writes) + ")";
  }
  return out;
}

}  // namespace pbr
