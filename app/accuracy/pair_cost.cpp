#include "app/accuracy/pair_cost.hpp"

#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "core/random.hpp"

namespace pbr {

namespace {

double lightingMs(const FrameTiming& f) { return f.pass("lighting"); }

}  // namespace

Scene pairCostScene(int lights) {
  Scene s;
  s.name = "pair-cost";
  s.camera.position = {0.0f, 3.0f, 0.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.fovYDeg = 45.0f;
  s.camera.nearPlane = 0.1f;
  s.camera.farPlane = 20.0f;
  s.addShape(Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(20.0f, 1.0f, 20.0f)),
             {glm::vec3(0.6f, 0.5f, 0.4f), 0.4f, 0.0f});
  Pcg32 random(0x5eed);
  for (int i = 0; i < lights; ++i) {
    PointLight l;
    l.position = {random.uniform(-3.0f, 3.0f), random.uniform(0.5f, 2.5f), random.uniform(-2.0f, 2.0f)};
    l.radius = 1000.0f;
    l.color = {random.uniform(0.2f, 1.0f), random.uniform(0.2f, 1.0f), random.uniform(0.2f, 1.0f)};
    l.luminousPower = 20.0f;
    s.lights.push_back(l);
  }
  return s;
}

std::vector<PairCost> measurePairCost(const ShaderLibrary& shaders, const std::vector<PairCostVariant>& variants,
                                      const PairCostSettings& settings,
                                      const std::function<void(int, int)>& progress) {
  const Scene scene = pairCostScene(settings.lights);
  struct Run {
    std::unique_ptr<Renderer> renderer;
    FrameOptions options;
    std::vector<double> withLights, withoutLights;  // lighting pass ms per round
  };
  std::vector<Run> runs;
  for (const PairCostVariant& v : variants) {
    RendererConfig config = v.config;
    config.sizeOption = settings.sizeOption;
    Run run{std::make_unique<Renderer>(shaders, scene, settings.size.x, settings.size.y, config), v.options, {}, {}};
    run.options.culling = Culling::None;
    run.options.stats = false;
    Profiler untimed(settings.timing);
    run.renderer->warmUp(run.options, untimed, 2);  // compiles the permutation before any timing
    runs.push_back(std::move(run));
  }
  const std::vector<PointLight> none;
  const int total = settings.rounds * static_cast<int>(runs.size());
  int done = 0;
  for (int round = 0; round < settings.rounds; ++round) {
    for (Run& run : runs) {
      Profiler profiler(settings.timing);
      run.renderer->renderFrame(run.options, profiler);
      run.renderer->setLights(none);
      run.renderer->renderFrame(run.options, profiler);
      run.renderer->setLights(scene.lights);
      const std::vector<FrameTiming> frames = profiler.takeResults(true);
      run.withLights.push_back(lightingMs(frames.at(0)));
      run.withoutLights.push_back(lightingMs(frames.at(1)));
      if (progress) progress(++done, total);
    }
  }
  const uint64_t pairs = uint64_t(settings.size.x) * uint64_t(settings.size.y) * uint64_t(settings.lights);
  std::vector<PairCost> out;
  for (size_t i = 0; i < runs.size(); ++i) {
    std::vector<double> ns;
    for (double ms : runs[i].withLights) ns.push_back(pairs ? ms * 1e6 / double(pairs) : 0.0);
    PairCost c{variants[i].name, summarizeTimes(ns), 0.0, pairs};
    const double withMs = summarizeTimes(runs[i].withLights).median;
    c.fixedShare = withMs > 0.0 ? summarizeTimes(runs[i].withoutLights).median / withMs : 0.0;
    out.push_back(c);
  }
  return out;
}

}  // namespace pbr
