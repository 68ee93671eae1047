#pragma once
#include <string>
#include <type_traits>

#include "core/gl/gl_objects.hpp"

namespace pbr {

// A uniform buffer holding exactly one std140 block mirrored by the C++ struct T.
template <class T>
class UniformBuffer {
  static_assert(std::is_trivially_copyable_v<T>, "std140 mirrors must be plain data");
  static_assert(sizeof(T) % 16 == 0, "std140 blocks are padded to a multiple of 16 bytes");

 public:
  explicit UniformBuffer(const std::string& label) : buffer_(label, sizeof(T)) {}
  UniformBuffer(const std::string& label, const T& value) : buffer_(label, sizeof(T), &value) {}
  void update(const T& value) { buffer_.upload(&value, sizeof(T)); }
  void bind(GLuint binding) const { buffer_.bindBase(GL_UNIFORM_BUFFER, binding); }

 private:
  Buffer buffer_;
};

}  // namespace pbr
