#include "app/file_clash.hpp"

#include <sys/stat.h>

#include <filesystem>

#include "app/args.hpp"
#include "core/io/output_file.hpp"
#include "core/scene/builtin_scenes.hpp"

namespace pbr {

namespace {

// Where a file's bytes live: its device and inode when it exists, else the path every link on it leads to.
struct FileIdentity {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string path;
  bool operator==(const FileIdentity& o) const {
    return exists && o.exists ? device == o.device && inode == o.inode : path == o.path;
  }
};

FileIdentity identify(const std::string& path) {
  FileIdentity id;
  id.path = followLinks(path);
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    id.exists = true;
    id.device = st.st_dev;
    id.inode = st.st_ino;
  }
  return id;
}

}  // namespace

std::vector<NamedFile> sceneInputs(const std::string& sceneName, const Scene& scene) {
  namespace fs = std::filesystem;
  std::vector<NamedFile> files;
  std::error_code ec;
  if (!isBuiltinScene(sceneName)) files.push_back({"--scene", sceneName});
  if (scene.environment && !scene.environment->file.empty()) {
    files.push_back({"the environment", scene.environment->file});
  }
  for (const auto& [path, loaded] : scene.gltfFiles) files.push_back({"a glTF model of the scene", path});
  for (const TextureData& t : scene.textures) {
    if (!t.name.empty() && fs::is_regular_file(t.name, ec)) files.push_back({"a texture of the scene", t.name});
  }
  return files;
}

void checkOutputsApart(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs) {
  std::vector<std::pair<const NamedFile*, FileIdentity>> seen;
  for (const NamedFile& in : inputs) {
    if (!in.path.empty()) seen.emplace_back(&in, identify(in.path));
  }
  const size_t inputCount = seen.size();
  for (const NamedFile& out : outputs) {
    if (out.path.empty() || isStreamTarget(out.path)) continue;
    const FileIdentity id = identify(out.path);
    for (size_t i = 0; i < seen.size(); ++i) {
      if (!(seen[i].second == id)) continue;
      const NamedFile& other = *seen[i].first;
      throw UsageError(out.role + " " + out.path + ": the same file as " + other.role + " " + other.path +
                       (i < inputCount ? ", which the command reads: writing it would replace it"
                                       : ": one would replace the other"));
    }
    seen.emplace_back(&out, id);
  }
}

}  // namespace pbr
