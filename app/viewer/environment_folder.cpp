#include "app/viewer/environment_folder.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/scene/assets.hpp"

namespace fs = std::filesystem;

namespace pbr {

std::string environmentFolder(const std::string& chosen, const std::optional<EnvironmentDesc>& current) {
  if (!chosen.empty()) return chosen;
  if (current && !current->file.empty()) return fs::absolute(current->file).lexically_normal().parent_path().string();
  return fs::absolute(fs::path(assetDir()) / "environments").lexically_normal().string();
}

std::vector<std::string> hdrFiles(const std::string& folder) {
  std::vector<std::string> files;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    std::string extension = it->path().extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::error_code unreadable;  // a broken link is left out, and the listing goes on
    if ((extension == ".hdr" || extension == ".exr") && it->is_regular_file(unreadable)) {
      files.push_back(it->path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace pbr
