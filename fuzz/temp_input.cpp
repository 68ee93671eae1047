#include "fuzz/temp_input.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace pbr::fuzz {

namespace {

namespace fs = std::filesystem;

fs::path baseFolder() {
  if (const char* env = std::getenv("PBR_FUZZ_TMP")) return env;
  if (fs::is_directory("/dev/shm")) return "/dev/shm";
  return fs::temp_directory_path();
}

// Created on first use; the destructor runs at normal exit (a crash leaves the folder, with the crashing input).
struct Folder {
  fs::path path = baseFolder() / ("pbr-fuzz-" + std::to_string(::getpid()));
  Folder() { fs::create_directories(path); }
  ~Folder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

}  // namespace

std::string writeTempInput(const std::string& name, const uint8_t* data, size_t size) {
  static const Folder folder;
  const fs::path path = folder.path / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out.flush()) throw std::runtime_error(path.string() + ": cannot write the fuzz input");
  return path.string();
}

}  // namespace pbr::fuzz
