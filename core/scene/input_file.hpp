#pragma once
#include <cstdint>
#include <string>

namespace pbr {

// Every input file the renderer reads (scene JSON, glTF and its buffers and images, textures, Radiance .hdr)
// comes through here, so that each refuses the same things with the same one-line message naming the file:
// what is not a regular file (a directory, a device such as /dev/zero, which would be read forever, a FIFO), and
// what is larger than `maxBytes`. Throws std::runtime_error.
constexpr uint64_t kMaxInputBytes = 2ull << 30;

// "PATH: not a regular file (a directory)", "PATH: cannot open: No such file or directory", ...
void requireRegularFile(const std::string& path, uint64_t maxBytes = kMaxInputBytes);
// The whole file, after requireRegularFile.
std::string readInputFile(const std::string& path, uint64_t maxBytes = kMaxInputBytes);

}  // namespace pbr
