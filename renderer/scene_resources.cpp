#include "renderer/scene_resources.hpp"

#include <stdexcept>
#include <string>

#include "core/gl/gl.hpp"
#include "lighting/lighting_options.hpp"

namespace pbr {

namespace {

std::unique_ptr<IblMaps> makeIbl(const ShaderLibrary& shaders, const Scene& scene, Profiler* profiler) {
  if (!scene.environment) return nullptr;
  const EnvironmentDesc& e = *scene.environment;
  const Environment environment = e.file.empty() ? Environment::sky(e.sky, e.intensity, e.rotationDeg)
                                                 : Environment::fromHdrFile(e.file, e.intensity, e.rotationDeg);
  // The picture is uploaded whole as one texture: a side past the context's limit is named before the upload.
  if (!environment.isSky()) {
    GLint limit = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &limit);
    const ImageRgbaF& image = environment.equirect();
    if (image.width > limit || image.height > limit) {
      throw std::runtime_error(e.file + ": " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                               " pixels, over the OpenGL limit of " + std::to_string(limit) +
                               " pixels a side (GL_MAX_TEXTURE_SIZE)");
    }
  }
  IblSettings settings;
  settings.sheen = usedLobes(scene).sheen;  // the sheen's cube map only for scenes with a sheen
  return std::make_unique<IblMaps>(shaders, environment, settings, profiler);
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
