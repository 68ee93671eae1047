#include "tests/shader_tree.hpp"

#include <doctest/doctest.h>

namespace pbr::test {

std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const ShaderError& e) {
    return e.what();
  }
  FAIL("expected a pbr::ShaderError");
  return {};
}

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

size_t occurrences(const std::string& haystack, const std::string& needle) {
  size_t count = 0;
  for (size_t at = haystack.find(needle); at != std::string::npos; at = haystack.find(needle, at + 1)) ++count;
  return count;
}

std::string describeDefines(const ShaderDefines& defines) {
  std::string out;
  for (const ShaderDefine& d : defines) out += d.name + "=" + d.value + " ";
  return out;
}

}  // namespace pbr::test
