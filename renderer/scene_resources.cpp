#include "renderer/scene_resources.hpp"

namespace pbr {

namespace {

std::unique_ptr<IblMaps> makeIbl(const ShaderLibrary& shaders, const Scene& scene, Profiler* profiler) {
  if (!scene.environment) return nullptr;
  const EnvironmentDesc& e = *scene.environment;
  const Environment environment = e.file.empty() ? Environment::sky(e.sky, e.intensity, e.rotationDeg)
                                                 : Environment::fromHdrFile(e.file, e.intensity, e.rotationDeg);
  return std::make_unique<IblMaps>(shaders, environment, IblSettings{}, profiler);
}

}  // namespace

SceneResources::SceneResources(const ShaderLibrary& shaders, const Scene& scene, Profiler* precomputeProfiler)
    : programs(shaders),
      geometry(programs, scene),
      ibl(makeIbl(shaders, scene, precomputeProfiler)),
      lighting(programs),
      post(programs),
      fxaa(programs),
      clusterDebug(programs),
      gbufferDebug(programs),
      efficiencyDebug(programs),
      shadowDebug(programs),
      transparencyDebug(programs) {
  lights.uploadPoints(scene.lights);
  lights.uploadDirectional(scene.directionalLights);
}

}  // namespace pbr
