#pragma once
#include <cstddef>

#include "core/gl/gl_objects.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

// Levels of a full mip chain down to 1x1.
int mipLevelCount(int width, int height);

// A decoded material image uploaded once, as SRGB8_ALPHA8 or RGBA8 with its full mip chain, and a sampler
// holding its glTF wrap modes and filters.
// Textures uploaded by this process so far: how tests check that a resize uploads no scene data again.
size_t gpuTextureUploads();

class GpuTexture {
 public:
  // Throws std::runtime_error naming the image if its pixels do not match its size or exceed the GL limit.
  explicit GpuTexture(const TextureData& data);
  const Texture& texture() const { return texture_; }
  const Sampler& sampler() const { return sampler_; }

 private:
  Texture texture_;
  Sampler sampler_;
};

}  // namespace pbr
