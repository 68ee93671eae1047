#pragma once
#include <string>

#include "core/scene/shading_model.hpp"
#include "gbuffer/gbuffer_precision.hpp"
#include "lighting/cluster_config.hpp"

namespace pbr {

class Profiler;  // core/gl/profiler.hpp

// What a renderer is built with, beyond the scene and the frame size.
struct RendererConfig {
  ClusterConfig clusters;
  HdrFormat hdrFormat = HdrFormat::Rgba16f;
  GBufferPrecision gbuffer = GBufferPrecision::Lean;
  Profiler* precomputeProfiler = nullptr;  // times the IBL precomputation when the scene has an environment
  std::string sizeOption = "--size";       // the option the frame size came from, named when it is too large
};

// The commands' configuration: the cluster grid's tile side timed on this machine (ClusterConfig::tileTrial).
RendererConfig measuredGrid();

}  // namespace pbr
