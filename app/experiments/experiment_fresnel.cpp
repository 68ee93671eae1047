#include <cmath>

#include <glm/gtc/constants.hpp>

#include "app/experiments/experiments.hpp"
#include "renderer/offscreen.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "reference/reference_brdf.hpp"

namespace pbr {

namespace {

// Red radiance of the centre pixel: with odd frame sides its ray is the view axis, which meets the floor at the
// fresnel-floor's mirror point, where the half vector equals the normal.
double centreRadiance(const ImageRgbaF& hdr) { return hdr.at(hdr.width / 2, hdr.height / 2)[0]; }

}  // namespace

ExperimentResult runFresnelExperiment(const ShaderLibrary& shaders, glm::ivec2 requested) {
  // Odd sides: one pixel more, or one less where that would pass the largest side --size takes (16384), so that
  // the frame stays within what was asked to be allowed.
  const auto odd = [](int side) { return side % 2 == 1 ? side : side < 16384 ? side + 1 : side - 1; };
  const glm::ivec2 size(odd(requested.x), odd(requested.y));
  ExperimentResult result;
  result.chartTitle = "Floor specular at the mirror direction: L / (I att) (PBR), L / att (Blinn-Phong)";
  result.yLabel = "reflected radiance per unit incident light";
  result.logY = true;
  result.table.xLabel = "view_angle_deg";
  result.table.columns = {"pbr", "blinn_phong"};
  for (float angle : {0.0f, 40.0f, 65.0f, 80.0f}) {
    SceneParams params;
    params.viewAngleDeg = angle;
    const Scene textured = makeBuiltinScene("fresnel-floor", params);
    // Specular only: a black base colour removes the diffuse term of both models but keeps F0 = 0.04.
    Scene specular = textured;
    specular.objects[0].material.baseColor = glm::vec3(0.0f);
    specular.objects[0].material.baseColorTexture = -1;
    const PointLight& light = specular.lights.at(0);
    const double att = reference::attenuation(glm::length(light.position - specular.camera.target), light.radius);
    const double intensity = light.luminousPower / (4.0 * glm::pi<double>());

    std::vector<double> row;
    for (ShadingModel model : {ShadingModel::Pbr, ShadingModel::BlinnPhong}) {
      FrameOptions options;
      options.model = model;
      options.exposure = textured.displayExposure();
      const double radiance = centreRadiance(renderOffscreen(shaders, specular, size, options, 1).hdr);
      row.push_back(model == ShadingModel::Pbr ? radiance / (intensity * att) : radiance / att);
      const std::string name = std::string("fresnel-") + toString(model) + "-" + std::to_string(int(angle)) + ".png";
      result.images.push_back({name, renderOffscreen(shaders, textured, size, options, 1).ldr});
    }
    result.table.x.push_back(angle);
    result.table.rows.push_back(row);
  }
  return result;
}

}  // namespace pbr
