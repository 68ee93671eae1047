#include "ibl/ibl_maps.hpp"

#include <stdexcept>
#include <string>

#include "core/gl/debug_group.hpp"
#include "core/gl/gpu_texture.hpp"
#include "ibl/dfg_table.hpp"
#include "ibl/environment_cubemap.hpp"
#include "ibl/irradiance_sh.hpp"
#include "ibl/sheen_prefilter.hpp"
#include "ibl/specular_prefilter.hpp"

namespace pbr {

namespace {

const IblSettings& checked(const IblSettings& s) {
  const auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("IBL settings: " + what);
  };
  require(s.faceSize >= 1 && s.faceSize <= 2048, "faceSize must be in [1, 2048]");
  const int chain = mipLevelCount(s.faceSize, s.faceSize);
  require(s.specularLevels >= 1 && s.specularLevels <= chain,
          "specularLevels must be in [1, " + std::to_string(chain) + "] for faceSize " + std::to_string(s.faceSize));
  // llvmpipe ends a shader invocation after 65535 loop iterations, silently (README, Limits).
  require(s.specularSamples >= 1 && s.specularSamples <= 65535, "specularSamples must be in [1, 65535]");
  require(s.dfgSize >= 2 && s.dfgSize <= 1024, "dfgSize must be in [2, 1024]");
  require(s.dfgSamples >= 1 && s.dfgSamples <= 65535, "dfgSamples must be in [1, 65535]");
  require(s.sheenFaceSize >= 1 && s.sheenFaceSize <= 512, "sheenFaceSize must be in [1, 512]");
  require(s.sheenLevels >= 1 && s.sheenLevels <= mipLevelCount(s.sheenFaceSize, s.sheenFaceSize),
          "sheenLevels must fit sheenFaceSize's mip chain");
  require(s.sheenSamples >= 1 && s.sheenSamples <= 65535, "sheenSamples must be in [1, 65535]");
  return s;
}

// Runs `step` as a pass: a debug group, and timed when there is a profiler.
template <class Step>
auto timed(Profiler* profiler, const char* name, Step&& step) {
  const ScopedPass pass(profiler, name);
  return step();
}

// Precomputation passes compiled up front, so that the timed passes measure GPU work only.
struct Passes {
  explicit Passes(const ShaderLibrary& shaders)
      : environment(shaders), irradiance(shaders), specular(shaders), dfg(shaders), sheen(shaders) {}
  EnvironmentCubemapPass environment;
  IrradianceShPass irradiance;
  SpecularPrefilterPass specular;
  DfgTablePass dfg;
  SheenPrefilterPass sheen;
};

}  // namespace

struct IblMaps::Maps {
  Buffer irradiance;
  Cubemap specular;
  Texture dfg;
  std::optional<Cubemap> sheen;
};

IblMaps::Maps IblMaps::precompute(const ShaderLibrary& shaders, const Environment& environment, const IblSettings& s,
                                  Profiler* profiler) {
  const DebugGroup group("ibl precompute");
  const Passes passes(shaders);
  if (profiler) profiler->beginFrame();
  const Cubemap source =
      timed(profiler, "ibl environment", [&] { return passes.environment.run(environment, s.faceSize); });
  Buffer irradiance = timed(profiler, "ibl irradiance", [&] { return passes.irradiance.run(source); });
  Cubemap specular = timed(profiler, "ibl specular",
                           [&] { return passes.specular.run(source, s.specularLevels, s.specularSamples); });
  Texture dfg = timed(profiler, "ibl dfg", [&] { return passes.dfg.run(s.dfgSize, s.dfgSamples); });
  std::optional<Cubemap> sheen;
  if (s.sheen) {
    sheen = timed(profiler, "ibl sheen",
                  [&] { return passes.sheen.run(source, s.sheenFaceSize, s.sheenLevels, s.sheenSamples); });
  }
  if (profiler) profiler->endFrame();
  return {std::move(irradiance), std::move(specular), std::move(dfg), std::move(sheen)};
}

IblMaps::IblMaps(const ShaderLibrary& shaders, const Environment& environment, const IblSettings& settings,
                 Profiler* profiler)
    : IblMaps(precompute(shaders, environment, checked(settings), profiler), settings) {}

IblMaps::IblMaps(Maps&& maps, const IblSettings& settings)
    : settings_(settings),
      irradiance_(std::move(maps.irradiance)),
      specular_(std::move(maps.specular)),
      dfg_(std::move(maps.dfg)),
      sheen_(std::move(maps.sheen)),
      specularSampler_("ibl.specular.sampler", GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR),
      dfgSampler_("ibl.dfg.sampler", GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_LINEAR, GL_LINEAR) {}

EnvironmentMaps IblMaps::maps() const {
  return {irradiance_.id(), specular_.id(), specularSampler_.id(), dfg_.id(), dfgSampler_.id(),
          sheen_ ? sheen_->id() : 0u};
}

size_t IblMaps::bytes() const {
  return irradiance_.size() + specular_.bytes() + (sheen_ ? sheen_->bytes() : 0) +
         static_cast<size_t>(dfg_.width()) * dfg_.height() * bytesPerTexel(dfg_.format());
}

}  // namespace pbr
