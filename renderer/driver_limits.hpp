#pragma once
#include <string>
#include <vector>

#include "core/gl/gl.hpp"
#include "renderer/frame_limits.hpp"

namespace pbr {

// The current context's limits and availableMemoryBytes().
FrameLimits queryFrameLimits();

// The internal formats of the frame's targets (G-buffer, depth, HDR, LDR, then the layout's channels).
std::vector<GLenum> frameFormats(const RendererConfig& config, const GBufferLayout& layout = {});

// Asks the driver, through proxy textures, whether it can create each of `formats` at width x height before
// anything is allocated: a driver may cap one texture's size (llvmpipe refuses textures over 1 GiB) well below
// GL_MAX_TEXTURE_SIZE squared and the memory available. Throws std::runtime_error naming `option` and the format.
void checkFrameFormats(int width, int height, const std::string& option, const std::vector<GLenum>& formats);

}  // namespace pbr
