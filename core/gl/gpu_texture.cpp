#include "core/gl/gpu_texture.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

namespace pbr {

namespace {

std::atomic<size_t> textureUploads{0};

const TextureData& checked(const TextureData& data) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (data.width < 1 || data.height < 1 || data.width > maxSize || data.height > maxSize) {
    throw std::runtime_error(data.name + ": " + std::to_string(data.width) + "x" + std::to_string(data.height) +
                             " is not a texture size this GL accepts (at most " + std::to_string(maxSize) + ")");
  }
  if (data.rgba.size() != static_cast<size_t>(data.width) * static_cast<size_t>(data.height) * 4) {
    throw std::runtime_error(data.name + ": pixel data does not match its " + std::to_string(data.width) + "x" +
                             std::to_string(data.height) + " size");
  }
  return data;
}

}  // namespace

int mipLevelCount(int width, int height) {
  int levels = 1;
  for (int size = std::max(width, height); size > 1; size /= 2) ++levels;
  return levels;
}

size_t gpuTextureUploads() { return textureUploads.load(); }

GpuTexture::GpuTexture(const TextureData& data)
    : texture_("texture " + data.name, data.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, checked(data).width, data.height,
               mipLevelCount(data.width, data.height)),
      sampler_("texture " + data.name + ".sampler", data.wrapS, data.wrapT, data.minFilter, data.magFilter) {
  ++textureUploads;
  // Rows go up from the top of the image, so glTF's uv (0,0), the image's top-left corner, is texel (0,0).
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(texture_.id(), 0, 0, 0, data.width, data.height, GL_RGBA, GL_UNSIGNED_BYTE, data.rgba.data());
  glGenerateTextureMipmap(texture_.id());
}

}  // namespace pbr
