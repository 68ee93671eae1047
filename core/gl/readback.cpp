#include "core/gl/readback.hpp"

#include <cstring>
#include <stdexcept>

namespace pbr {

namespace {

template <class T>
std::vector<T> readback(const Texture& texture, GLenum type) {
  const size_t rowElems = static_cast<size_t>(texture.width()) * 4;
  const size_t bytes = rowElems * texture.height() * sizeof(T);
  Buffer pbo("readback.pixels", bytes, nullptr, GL_MAP_READ_BIT);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, pbo.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(texture.id(), 0, GL_RGBA, type, static_cast<GLsizei>(bytes), nullptr);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  const auto* mapped = static_cast<const T*>(glMapNamedBufferRange(pbo.id(), 0, static_cast<GLsizeiptr>(bytes), GL_MAP_READ_BIT));
  std::vector<T> out(rowElems * texture.height());
  if (!mapped) throw std::runtime_error("could not map the read-back buffer");
  for (int y = 0; y < texture.height(); ++y) {
    std::memcpy(&out[static_cast<size_t>(y) * rowElems], mapped + static_cast<size_t>(texture.height() - 1 - y) * rowElems,
                rowElems * sizeof(T));
  }
  glUnmapNamedBuffer(pbo.id());
  return out;
}

}  // namespace

ImageRgba8 readbackRgba8(const Texture& texture) {
  return {texture.width(), texture.height(), readback<uint8_t>(texture, GL_UNSIGNED_BYTE)};
}

ImageRgbaF readbackRgbaF(const Texture& texture) {
  return {texture.width(), texture.height(), readback<float>(texture, GL_FLOAT)};
}

}  // namespace pbr
