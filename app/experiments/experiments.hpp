#pragma once
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/gl/shader_library.hpp"
#include "core/scene/image.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

// A table an experiment measured: one row per x value, one column per series.
struct ExperimentTable {
  std::string xLabel;
  std::vector<std::string> columns;
  std::vector<double> x;
  std::vector<std::vector<double>> rows;  // rows[i][j]: column j at x[i]
  double at(size_t row, const std::string& column) const;
};

// Images an experiment rendered, by file name.
struct ExperimentImage {
  std::string file;
  ImageRgba8 image;
};

struct ExperimentResult {
  ExperimentTable table;
  std::vector<ExperimentImage> images;
  std::string chartTitle, yLabel;
  bool logX = false, logY = false;
};

// Specular reflectance of the fresnel-floor at the mirror direction for view angles 0, 40, 65 and 80 degrees,
// both models: the radiance of a specular-only floor at the mirror point over the light's incident scale
// (PBR: I * attenuation, giving f_s n.l; Blinn-Phong: attenuation, giving its constant F0). Frame sides are
// made odd so that the centre pixel sees the mirror point.
ExperimentResult runFresnelExperiment(const ShaderLibrary& shaders, glm::ivec2 size);

// Fully saturated pixels (HSV value 255) of the light-wall lit by 1..maxLights co-located lights, both models.
ExperimentResult runSaturationExperiment(const ShaderLibrary& shaders, glm::ivec2 size, int maxLights = 10);

// Frame time of both models under 100 lights as the scene's triangle count grows.
ExperimentResult runTrianglesExperiment(const ShaderLibrary& shaders, glm::ivec2 size, int frames);

// The tone curves (--tonemap): each curve's display value of a grey ramp over 16 stops around mid grey, and one
// frame of `scene` at its metered exposure under every curve, side by side (tonemap-strip.png: the centre square
// of each, in kToneCurves order).
ExperimentResult runToneMapExperiment(const ShaderLibrary& shaders, glm::ivec2 size, const Scene& scene);

// Writes the table as CSV (x column first).
void writeExperimentCsv(const std::string& path, const ExperimentTable& table);

}  // namespace pbr
