#include "renderer/frame_limits.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "renderer/renderer_config.hpp"

namespace pbr {

namespace {

constexpr uint64_t kUnlimited = std::numeric_limits<uint64_t>::max();

uint64_t hdrBytesPerPixel(HdrFormat format) {
  switch (format) {
    case HdrFormat::Rgba16f: return 8;
    case HdrFormat::R11g11b10f: return 4;
    case HdrFormat::Rgba32f: return 16;
  }
  return 16;
}

// "MemAvailable:   23834564 kB"
uint64_t meminfoAvailable() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  uint64_t kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit) {
    if (key == "MemAvailable:") return kb * 1024;
  }
  const long pages = ::sysconf(_SC_AVPHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && pageSize > 0 ? static_cast<uint64_t>(pages) * static_cast<uint64_t>(pageSize) : kUnlimited;
}

// cgroup v2: "max" or a byte count.
uint64_t readCgroupValue(const char* path) {
  std::ifstream in(path);
  uint64_t value = 0;
  return in >> value ? value : kUnlimited;
}

uint64_t cgroupAvailable() {
  const uint64_t max = readCgroupValue("/sys/fs/cgroup/memory.max");
  if (max == kUnlimited) return kUnlimited;
  const uint64_t current = readCgroupValue("/sys/fs/cgroup/memory.current");
  return current == kUnlimited || current >= max ? 0 : max - current;
}

uint64_t addressSpaceAvailable() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kUnlimited;
  // /proc/self/statm: total program size in pages first.
  std::ifstream in("/proc/self/statm");
  uint64_t pages = 0;
  if (!(in >> pages)) return limit.rlim_cur;
  const uint64_t used = pages * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
  return used >= limit.rlim_cur ? 0 : limit.rlim_cur - used;
}

std::string gigabytes(uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GB", static_cast<double>(bytes) / 1e9);
  return text;
}

}  // namespace

uint64_t frameBytesPerPixel(const RendererConfig& config, const GBufferLayout& layout, bool transmission) {
  const uint64_t gbuffer =
      uint64_t(gbufferBytesPerPixel(config.gbuffer)) + uint64_t(layout.extraBytesPerPixel(config.gbuffer));
  const uint64_t ldr = 2 * 4;  // the display image, and its copy before anti-aliasing (made on first use)
  const uint64_t captures = 2 * 4 + 2 * 16;  // RGBA8 and RGBA32F read-backs, each a buffer and an image
  const uint64_t runningSums = 16;  // RGBA32F, made for frames whose lights take several lighting dispatches
  const uint64_t pairCounts = 8;    // RG32UI, made for the efficiency debug channel
  const uint64_t shadowLight = 8;   // RG32F, made for the shadows debug channel
  const uint64_t background = transmission ? transmissionBackgroundBytesPerPixel(config.hdrFormat) : 0;
  return gbuffer + hdrBytesPerPixel(config.hdrFormat) + ldr + captures + runningSums + pairCounts + shadowLight +
         background;
}

uint64_t transmissionBackgroundBytesPerPixel(HdrFormat format) { return (4 * hdrBytesPerPixel(format) + 2) / 3; }

uint64_t availableMemoryBytes() {
  return std::min({meminfoAvailable(), cgroupAvailable(), addressSpaceAvailable()});
}

void checkFrameSize(int width, int height, const std::string& option, uint64_t bytesPerPixel,
                    const FrameLimits& limits) {
  const std::string size = option + " " + std::to_string(width) + "x" + std::to_string(height);
  if (width > limits.maxTextureSize || height > limits.maxTextureSize) {
    throw std::runtime_error(size + ": over the OpenGL limit of " + std::to_string(limits.maxTextureSize) +
                             " pixels a side (GL_MAX_TEXTURE_SIZE)");
  }
  const uint64_t bytes = static_cast<uint64_t>(width) * static_cast<uint64_t>(height) * bytesPerPixel;
  if (bytes > limits.availableBytes) {
    throw std::runtime_error(size + ": the frame needs about " + gigabytes(bytes) + " (" +
                             std::to_string(bytesPerPixel) + " bytes per pixel), over the " +
                             gigabytes(limits.availableBytes) + " of memory available");
  }
}

}  // namespace pbr
