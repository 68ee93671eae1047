#include <algorithm>

#include "app/experiments/experiments.hpp"
#include "renderer/offscreen.hpp"
#include "core/scene/builtin_scenes.hpp"

namespace pbr {

namespace {

// HSV value is the largest channel: a pixel is fully saturated when it reaches 255.
int saturatedPixels(const ImageRgba8& image) {
  int n = 0;
  for (size_t i = 0; i < image.pixels.size(); i += 4) {
    n += std::max({image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]}) == 255;
  }
  return n;
}

}  // namespace

ExperimentResult runSaturationExperiment(const ShaderLibrary& shaders, glm::ivec2 size, int maxLights) {
  ExperimentResult result;
  result.chartTitle = "Fully saturated pixels (HSV value 255) vs co-located lights";
  result.yLabel = "saturated pixels";
  result.table.xLabel = "lights";
  result.table.columns = {"pbr", "blinn_phong"};
  for (int n = 1; n <= maxLights; ++n) {
    SceneParams params;
    params.lights = n;
    const Scene scene = makeBuiltinScene("light-wall", params);
    std::vector<double> row;
    for (ShadingModel model : {ShadingModel::Pbr, ShadingModel::BlinnPhong}) {
      FrameOptions options;
      options.model = model;
      options.exposure = scene.displayExposure();
      const RenderedFrames frames = renderOffscreen(shaders, scene, size, options, 1);
      row.push_back(saturatedPixels(frames.ldr));
      if (n == 1 || n == maxLights) {
        result.images.push_back({std::string("saturation-") + toString(model) + "-" + std::to_string(n) + ".png", frames.ldr});
      }
    }
    result.table.x.push_back(n);
    result.table.rows.push_back(row);
  }
  return result;
}

}  // namespace pbr
