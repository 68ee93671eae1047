#pragma once
#include "app/args.hpp"
#include "app/render_settings.hpp"
#include "renderer/frame_options.hpp"
#include "renderer/renderer_config.hpp"

namespace pbr {

// What a settings record decides of a frame in the renderer's own types: its configuration (HDR target, G-buffer,
// cluster grid and assignment) and its frame options (model and terms, culling, shadows, transparency, tone curve,
// anti-aliasing, debug channel). The scene, size, exposure and outputs the record holds are read where the scene
// is loaded.
struct FrameSettings {
  RendererConfig renderer;
  FrameOptions frame;
};

// Whether `option` is one frameSettings() reads.
bool isFrameSetting(const std::string& option);

// `settings` with the options of `record` that decide it applied (its other options left to their readers); one
// parser for a command line's record (pbr render), a report's and an accuracy variant's. Throws UsageError naming
// the option and its value for a value it does not take, or for options that contradict each other (a term of the
// other model, --visibility beside --variant's visibility, a cluster debug channel without clustered culling).
FrameSettings frameSettings(const RenderSettings& record, FrameSettings settings = {});

}  // namespace pbr
