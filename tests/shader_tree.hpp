#pragma once
// What the shader library's tests share: a scratch shader tree and the text checks they make on what it expands to.
#include <filesystem>
#include <functional>
#include <string>

#include "core/scene/shader_sources.hpp"
#include "tests/cli_util.hpp"

namespace pbr::test {

// A scratch shader root, one per instance, removed afterwards.
class TempShaderTree {
 public:
  const std::filesystem::path& root() const { return dir_.path(); }
  // How the library names a file of this tree in its messages: the root folder's name, then the relative path.
  std::string display(const std::string& relative) const { return root().filename().string() + "/" + relative; }
  void write(const std::string& relative, const std::string& text) const { dir_.write(relative, text); }

 private:
  TempDir dir_;
};

inline constexpr const char* kComputeHeader = "#version 450 core\nlayout(local_size_x = 1) in;\n";

// The message of the pbr::ShaderError `action` throws; fails the test case when it throws none.
std::string errorOf(const std::function<void()>& action);

bool contains(const std::string& haystack, const std::string& needle);
size_t occurrences(const std::string& haystack, const std::string& needle);

// "NAME=VALUE " for each define, in order.
std::string describeDefines(const ShaderDefines& defines);

}  // namespace pbr::test
