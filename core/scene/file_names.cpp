#include "core/scene/file_names.hpp"

#include <cctype>
#include <filesystem>

namespace pbr {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace pbr
