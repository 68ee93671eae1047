#pragma once
#include <memory>

#include "core/gl/profiler.hpp"
#include "core/gl/program_cache.hpp"
#include "core/scene/scene.hpp"
#include "debug/cluster_debug_pass.hpp"
#include "debug/efficiency_debug_pass.hpp"
#include "debug/gbuffer_debug_pass.hpp"
#include "debug/shadow_debug_pass.hpp"
#include "debug/transparency_debug_pass.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "ibl/ibl_maps.hpp"
#include "lighting/light_buffer.hpp"
#include "lighting/lighting_pass.hpp"
#include "post/fxaa_pass.hpp"
#include "post/post_pass.hpp"
#include "shadows/shadow_pass.hpp"

namespace pbr {

// What lives as long as the scene, whatever the frame size: the program cache (every pass's permutations, the
// cluster passes' too), the uploaded meshes, textures and material blocks (inside the G-buffer pass), the light
// buffer, the shadow atlas, the IBL maps precomputed from the scene's environment, and the passes that hold no per-size state.
// Built once per scene; a resize does not touch it.
struct SceneResources {
  // Throws what the IBL precomputation throws (an unusable .hdr, named). With a profiler the precomputation is
  // one profiler frame of its own (ibl/README.md), so the profiler must not be inside a frame.
  SceneResources(const ShaderLibrary& shaders, const Scene& scene, Profiler* precomputeProfiler);

  ProgramCache programs;  // first: the passes below hold references into it
  GBufferPass geometry;
  LightBuffer lights;
  std::unique_ptr<IblMaps> ibl;  // null without an environment
  LightingPass lighting;
  ShadowPass shadows;  // allocates its atlas on the first shadowed frame
  PostPass post;
  std::unique_ptr<ExposureMeter> exposureMeter;  // made by the first frame with automatic exposure
  FxaaPass fxaa;
  ClusterDebugPass clusterDebug;
  GBufferDebugPass gbufferDebug;
  EfficiencyDebugPass efficiencyDebug;
  ShadowDebugPass shadowDebug;
  TransparencyDebugPass transparencyDebug;
  UniformBuffer<LegendBlock> debugLegend{"debug.legend"};  // the text of the debug channel's legend, set by the frame that shows it
};

}  // namespace pbr
