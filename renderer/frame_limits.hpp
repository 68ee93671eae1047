#pragma once
#include <cstdint>
#include <string>

#include "gbuffer/gbuffer_precision.hpp"

namespace pbr {

struct RendererConfig;

// What bounds the frame size a Renderer may allocate, checked before any target exists so that an impossible
// --size fails at once by name instead of after minutes of rendering with a raw GL error.
struct FrameLimits {
  int maxTextureSize = 0;       // GL_MAX_TEXTURE_SIZE of the current context
  uint64_t availableBytes = 0;  // memory the process may still take (availableMemoryBytes)
};

// Bytes per pixel a Renderer holds for a frame: the G-buffer (with the channels of the scene's layout), HDR and LDR
// targets (the LDR twice, for the image anti-aliasing reads), the running sums of chunked lighting, the efficiency
// channel's pair counts, and one capture of each (read-back buffer plus the image copied out of it). Textures are
// counted against host memory because the software rasterizer keeps them there and a discrete GPU's driver shadows
// read-backs in it.
uint64_t frameBytesPerPixel(const RendererConfig& config, const GBufferLayout& layout = {});

// The smallest of /proc/meminfo's MemAvailable, the cgroup's memory.max less memory.current, and the address
// space left under RLIMIT_AS: whichever stops an allocation first.
uint64_t availableMemoryBytes();

// Throws std::runtime_error naming `option` (the command-line option the size came from, "--size") and the limit
// the frame is over.
void checkFrameSize(int width, int height, const std::string& option, uint64_t bytesPerPixel,
                    const FrameLimits& limits);

}  // namespace pbr
