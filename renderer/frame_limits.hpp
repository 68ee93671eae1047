#pragma once
#include <cstdint>
#include <string>

#include "core/scene/shading_model.hpp"
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
// channel's pair counts, one capture of each (read-back buffer plus the image copied out of it), and for a scene with
// transmissive materials (`transmission`) the copy of the opaque frame they see through, with its mip chain (4/3 of
// the HDR target, rounded up). Textures are counted against host memory because the software rasterizer keeps them
// there and a discrete GPU's driver shadows read-backs in it.
uint64_t frameBytesPerPixel(const RendererConfig& config, const GBufferLayout& layout = {}, bool transmission = false);
// The copy of the opaque frame transmissive materials see through: bytes per pixel of the frame, the HDR target's
// with its mip chain, 4/3 of them rounded up.
uint64_t transmissionBackgroundBytesPerPixel(HdrFormat format);

// The smallest of /proc/meminfo's MemAvailable, the cgroup's memory.max less memory.current, and the address
// space left under RLIMIT_AS: whichever stops an allocation first.
uint64_t availableMemoryBytes();

// Throws std::runtime_error naming `option` (the command-line option the size came from, "--size") and the limit
// the frame is over.
void checkFrameSize(int width, int height, const std::string& option, uint64_t bytesPerPixel,
                    const FrameLimits& limits);

}  // namespace pbr
