#include <glm/gtc/matrix_transform.hpp>

#include "app/experiments/experiments.hpp"
#include "app/bench/frame_stats.hpp"
#include "renderer/offscreen.hpp"
#include "core/scene/builtin_scenes.hpp"

namespace pbr {

namespace {

// A floor and a 5x5 grid of spheres tessellated with `segments` x segments/2 quads each, under 100 lights.
Scene tessellatedScene(int segments) {
  Scene s;
  s.name = "triangles";
  s.camera.position = {0.0f, 4.0f, 9.0f};
  s.camera.target = {0.0f, 0.5f, 0.0f};
  s.camera.nearPlane = 0.5f;
  s.camera.farPlane = 40.0f;
  s.ambient = glm::vec3(0.02f);
  s.addShape(Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(20.0f, 1.0f, 20.0f)), Material{glm::vec3(0.5f), 0.7f, 0.0f});
  s.meshes.push_back(makeSphereMesh(segments, segments / 2));
  const int sphereMesh = static_cast<int>(s.meshes.size()) - 1;
  for (int ix = 0; ix < 5; ++ix) {
    for (int iz = 0; iz < 5; ++iz) {
      const glm::vec3 c((ix - 2) * 1.4f, 0.6f, (iz - 2) * 1.4f);
      const glm::mat4 t = glm::scale(glm::translate(glm::mat4(1.0f), c), glm::vec3(1.2f));
      s.objects.push_back({Shape::Sphere, sphereMesh, t, Material{glm::vec3(0.8f, 0.6f, 0.4f), 0.1f + 0.04f * (ix + 5 * iz), ix % 2 ? 1.0f : 0.0f}});
    }
  }
  RandomLightSpec spec;
  spec.count = 100;
  spec.boundsMin = {-5.0f, 0.3f, -5.0f};
  spec.boundsMax = {5.0f, 2.5f, 5.0f};
  spec.radiusMin = 1.5f;
  spec.radiusMax = 4.0f;
  spec.powerMin = 5.0f;
  spec.powerMax = 30.0f;
  s.lights = makeRandomLights(spec);
  return s;
}

size_t triangleCount(const Scene& s) {
  size_t n = 0;
  for (const SceneObject& o : s.objects) n += s.meshes[static_cast<size_t>(o.mesh)].indices.size() / 3;
  return n;
}

}  // namespace

ExperimentResult runTrianglesExperiment(const ShaderLibrary& shaders, glm::ivec2 size, int frames) {
  ExperimentResult result;
  const TimingMode timing = chooseTimingMode("auto", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  result.chartTitle = std::string("Frame time vs triangles, 100 lights (") + describe(timing) + ")";
  result.yLabel = "frame time (ms, median)";
  result.logX = true;
  result.table.xLabel = "triangles";
  result.table.columns = {"pbr_frame_ms", "blinn_phong_frame_ms", "pbr_gbuffer_ms", "blinn_phong_gbuffer_ms"};
  for (int segments : {8, 16, 32, 64, 128, 256}) {
    const Scene scene = tessellatedScene(segments);
    std::vector<double> frameMs, gbufferMs;
    for (ShadingModel model : {ShadingModel::Pbr, ShadingModel::BlinnPhong}) {
      FrameOptions options;
      options.model = model;
      const RenderedFrames r = renderOffscreen(shaders, scene, size, options, frames + 1, {}, timing);
      // The first frame compiles shaders and sizes buffers: time only the ones after it.
      const std::vector<FrameTiming> warm(r.timings.begin() + 1, r.timings.end());
      std::vector<double> frame;
      for (const FrameTiming& f : warm) frame.push_back(f.gpuMs);
      frameMs.push_back(median(frame));
      gbufferMs.push_back(medianPassTimes(warm).front().ms);
      if (segments == 256) result.images.push_back({std::string("triangles-") + toString(model) + ".png", r.ldr});
    }
    result.table.x.push_back(static_cast<double>(triangleCount(scene)));
    result.table.rows.push_back({frameMs[0], frameMs[1], gbufferMs[0], gbufferMs[1]});
  }
  return result;
}

}  // namespace pbr
