#include "renderer/renderer_config.hpp"

namespace pbr {

RendererConfig measuredGrid() {
  RendererConfig config;
  config.clusters.tileTrial = true;
  return config;
}

}  // namespace pbr
