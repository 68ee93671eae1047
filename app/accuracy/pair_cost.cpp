#include "app/accuracy/pair_cost.hpp"

#include <map>
#include <memory>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/random.hpp"
#include "renderer/renderer.hpp"

namespace pbr {

namespace {

Material withLobe(Material m, FixtureMaterial material) {
  switch (material) {
    case FixtureMaterial::Core: break;
    case FixtureMaterial::Specular:
      m.ior = 1.33f;
      m.specularColor = {1.0f, 0.8f, 0.6f};
      break;
    case FixtureMaterial::Clearcoat:
      m.clearcoat = 1.0f;
      m.clearcoatRoughness = 0.1f;
      break;
    case FixtureMaterial::Sheen:
      m.sheenColor = {1.0f, 0.8f, 0.6f};
      m.sheenRoughness = 0.5f;
      break;
  }
  return m;
}

}  // namespace

Scene pairCostScene(int lights, FixtureMaterial material) {
  Scene s;
  s.name = "pair-cost";
  s.camera.position = {0.0f, 3.0f, 0.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.fovYDeg = 45.0f;
  s.camera.nearPlane = 0.1f;
  s.camera.farPlane = 20.0f;
  s.addShape(Shape::Plane, glm::scale(glm::mat4(1.0f), glm::vec3(20.0f, 1.0f, 20.0f)),
             withLobe({glm::vec3(0.6f, 0.5f, 0.4f), 0.4f, 0.0f}, material));
  Material pane = withLobe({glm::vec3(0.4f, 0.5f, 0.6f), 0.4f, 0.0f}, material);
  pane.alpha = 0.5f;
  pane.alphaMode = AlphaMode::Blend;
  s.addShape(Shape::Plane,
             glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 0.3f, 0.0f}), glm::vec3(20.0f, 1.0f, 20.0f)), pane);
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
                                      const PairCostSettings& settings, const Scene* scene,
                                      const std::function<void(int, int)>& progress) {
  // One fixture per material in use, or the scene; a node of the map stays where it is, as each Renderer keeps its
  // scene. Beside each, the same without lights, for the pass's work that is not per pair: a renderer of its own, so
  // that taking the lights away never resizes the measured renderer's light lists.
  std::map<FixtureMaterial, Scene> scenes, unlit;
  for (const PairCostVariant& v : variants) {
    if (scenes.count(v.material)) continue;
    scenes.emplace(v.material, scene ? *scene : pairCostScene(settings.lights, v.material));
    Scene dark = scenes.at(v.material);
    dark.lights.clear();
    unlit.emplace(v.material, std::move(dark));
  }
  struct Run {
    std::unique_ptr<Renderer> renderer, unlit;
    FrameOptions options;
    uint64_t pairs = 0;  // evaluated per frame
    // Per round, the lighting and transparency passes' ms.
    std::vector<double> withLights, withoutLights, blendedWithLights, blendedWithoutLights;
  };
  std::vector<Run> runs;
  for (const PairCostVariant& v : variants) {
    RendererConfig config = v.config;
    config.sizeOption = settings.sizeOption;
    const glm::ivec2 size = settings.size;
    Run run;
    run.renderer = std::make_unique<Renderer>(shaders, scenes.at(v.material), size.x, size.y, config);
    run.unlit = std::make_unique<Renderer>(shaders, unlit.at(v.material), size.x, size.y, config);
    run.options = v.options;
    run.options.culling = v.culling;
    run.options.stats = false;
    Profiler untimed(settings.timing);
    run.renderer->warmUp(run.options, untimed, 2);  // compiles the permutation and sizes the lists before timing
    run.unlit->warmUp(run.options, untimed, 2);
    run.pairs = uint64_t(size.x) * uint64_t(size.y) * uint64_t(settings.lights);
    if (scene) {
      FrameOptions counted = run.options;
      counted.stats = true;
      run.renderer->renderFrame(counted, untimed);
      run.pairs = run.renderer->lightStats().pairs.evaluated;
    }
    runs.push_back(std::move(run));
  }
  const int total = settings.rounds * static_cast<int>(runs.size());
  int done = 0;
  for (int round = 0; round < settings.rounds; ++round) {
    for (Run& run : runs) {
      Profiler profiler(settings.timing);
      run.renderer->renderFrame(run.options, profiler);
      run.unlit->renderFrame(run.options, profiler);
      const std::vector<FrameTiming> frames = profiler.takeResults(true);
      run.withLights.push_back(frames.at(0).pass("lighting"));
      run.withoutLights.push_back(frames.at(1).pass("lighting"));
      run.blendedWithLights.push_back(frames.at(0).pass("transparency"));
      run.blendedWithoutLights.push_back(frames.at(1).pass("transparency"));
      if (progress) progress(++done, total);
    }
  }
  std::vector<PairCost> out;
  // ns per pair of each round, and the pass without lights over the pass with them (medians).
  const auto perPair = [](const std::vector<double>& ms, uint64_t pairs) {
    std::vector<double> ns;
    for (double m : ms) ns.push_back(pairs ? m * 1e6 / double(pairs) : 0.0);
    return summarizeTimes(ns);
  };
  const auto fixedShare = [](const std::vector<double>& with, const std::vector<double>& without) {
    const double withMs = summarizeTimes(with).median;
    return withMs > 0.0 ? summarizeTimes(without).median / withMs : 0.0;
  };
  for (size_t i = 0; i < runs.size(); ++i) {
    const Run& r = runs[i];
    PairCost c;
    c.name = variants[i].name;
    c.material = variants[i].material;
    c.culling = variants[i].culling;
    c.nsPerPair = perPair(r.withLights, r.pairs);
    c.fixedShare = fixedShare(r.withLights, r.withoutLights);
    c.pairs = r.pairs;
    // The fixture's pane lies over every pixel of the floor: the same pairs. A scene's BLEND surfaces are not timed.
    if (!scene) {
      c.transparentNsPerPair = perPair(r.blendedWithLights, r.pairs);
      c.transparentFixedShare = fixedShare(r.blendedWithLights, r.blendedWithoutLights);
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace pbr
