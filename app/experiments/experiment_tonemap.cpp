#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/experiments/experiments.hpp"
#include "core/scene/builtin_scenes.hpp"
#include "core/scene/exposure.hpp"
#include "renderer/display_image.hpp"
#include "renderer/renderer.hpp"

namespace pbr {

namespace {

// The tone curves' inputs: mid grey (0.18) times 2^stop, from 8 stops below to 8 above, in quarter stops.
constexpr double kLowStop = -8.0, kHighStop = 8.0, kStopStep = 0.25;
constexpr int kPanelGap = 4;  // black pixels between the strip's panels

// The centre square of `image` (the full height): the strip stays as wide as a README can show.
ImageRgba8 centreSquare(const ImageRgba8& image) {
  const int side = std::min(image.width, image.height), x0 = (image.width - side) / 2, y0 = (image.height - side) / 2;
  ImageRgba8 out{side, side, std::vector<uint8_t>(size_t(side) * size_t(side) * 4)};
  for (int y = 0; y < side; ++y) {
    std::copy_n(&image.pixels[(size_t(y0 + y) * size_t(image.width) + size_t(x0)) * 4], size_t(side) * 4,
                &out.pixels[size_t(y) * size_t(side) * 4]);
  }
  return out;
}

// Panels left to right with kPanelGap black columns between them; every panel has the first one's size.
ImageRgba8 sideBySide(const std::vector<ImageRgba8>& panels) {
  const int w = panels.front().width, h = panels.front().height, n = int(panels.size());
  ImageRgba8 out{n * w + (n - 1) * kPanelGap, h, {}};
  out.pixels.assign(size_t(out.width) * size_t(h) * 4, 0);
  for (size_t i = 3; i < out.pixels.size(); i += 4) out.pixels[i] = 255;
  for (int p = 0; p < n; ++p) {
    for (int y = 0; y < h; ++y) {
      std::copy_n(&panels[size_t(p)].pixels[size_t(y) * size_t(w) * 4], size_t(w) * 4,
                  &out.pixels[(size_t(y) * size_t(out.width) + size_t(p * (w + kPanelGap))) * 4]);
    }
  }
  return out;
}

}  // namespace

ExperimentResult runToneMapExperiment(const ShaderLibrary& shaders, glm::ivec2 size, const Scene& scene) {
  ExperimentResult result;
  result.chartTitle = "Tone curves: display value of mid grey (0.18) times 2^stops, after exposure";
  result.yLabel = "8-bit sRGB code";
  result.table.xLabel = "stops_from_mid_grey";
  for (const ToneCurve curve : kToneCurves) result.table.columns.push_back(toString(curve));

  // The curves themselves: a grey ramp through the post pass, exposure 1.
  ImageRgbaF ramp{0, 1, {}};
  for (double stop = kLowStop; stop <= kHighStop + 1e-9; stop += kStopStep) {
    const float v = float(0.18 * std::exp2(stop));
    ramp.pixels.insert(ramp.pixels.end(), {v, v, v, 1.0f});
    result.table.x.push_back(stop);
  }
  ramp.width = int(result.table.x.size());
  result.table.rows.assign(result.table.x.size(), {});
  for (const ToneCurve curve : kToneCurves) {
    const ImageRgba8 shown = displayImage(shaders, ramp, 1.0f, curve);
    for (size_t i = 0; i < result.table.x.size(); ++i) result.table.rows[i].push_back(shown.pixels[i * 4]);
  }

  // The frame: its radiance once, at the exposure the meter chooses, shown under every curve.
  Renderer renderer(shaders, scene, size.x, size.y);
  Profiler profiler(TimingMode::Serializing);
  FrameOptions options;
  options.exposure = scene.displayExposure();
  options.autoExposure = true;
  ImageRgbaF hdr;
  renderer.renderFrame(options, profiler);  // sizes the clusters' lists from measured demand
  renderer.renderFrame(options, profiler, {nullptr, &hdr});
  const double ev100 = renderer.meteredExposure()->ev100;
  std::vector<ImageRgba8> panels;
  for (const ToneCurve curve : kToneCurves) {
    panels.push_back(centreSquare(displayImage(shaders, hdr, float(exposureFromEv100(ev100)), curve)));
  }
  result.images.push_back({"tonemap-strip.png", sideBySide(panels)});
  std::printf("strip: %s at EV100 %.2f (metered), left to right:", scene.name.c_str(), ev100);
  for (const ToneCurve curve : kToneCurves) std::printf(" %s", toString(curve));
  std::printf("\n");
  return result;
}

}  // namespace pbr
