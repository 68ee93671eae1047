#pragma once
#include <string>
#include <vector>

#include "core/scene/scene.hpp"

namespace pbr {

// A file a command reads or writes, as its command line names it: `role` says which ("--json", "--scene", "shard
// 2").
struct NamedFile {
  std::string role;
  std::string path;
};

// The files a loaded scene was read from: the scene file (unless `sceneName` is a built-in), its environment image,
// its glTF models and its texture files.
std::vector<NamedFile> sceneInputs(const std::string& sceneName, const Scene& scene);

// Throws UsageError before any work when an output is the same file as an input or as another output, however each
// is named: symbolic links followed (a dangling one to the file it would make), hard links by device and inode.
// Devices, FIFOs and sockets (/dev/null, /dev/stdout) may be named more than once. Empty paths are left out.
void checkOutputsApart(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs);

}  // namespace pbr
