#include "ibl/environment_cubemap.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "core/gl/gpu_texture.hpp"
#include "core/gl/uniform_buffer.hpp"

namespace pbr {

namespace {

// Mirrors EnvironmentPassBlock in shaders/ibl/environment_cubemap.comp.
struct EnvironmentPassBlock {
  glm::vec4 sunDirection;  // xyz: unit vector to the sun; w: its angular radius as rendered (radians)
  glm::vec4 sunRadiance;   // rgb, as rendered
  glm::vec4 zenith;
  glm::vec4 horizon;
  glm::vec4 ground;
  glm::vec4 params;        // x: cos(rotation), y: sin(rotation), z: intensity
  glm::ivec4 sizes;        // x: face size, y: subsamples per texel side
};
static_assert(sizeof(EnvironmentPassBlock) == 112, "std140 layout of EnvironmentPassBlock");

constexpr double kPi = 3.14159265358979323846;
constexpr GLuint kGroupSize = 8;
// The sky's subsamples per texel side: enough for the sun's anti-aliased edge to keep the disc's area.
constexpr int kSkySubsamples = 4;
// 64 directions per texel: enough for an 8k panorama in 256^2 faces; beyond, the faces should grow instead.
constexpr int kMaxSubsamples = 8;

EnvironmentPassBlock passBlock(const Environment& environment, int faceSize) {
  EnvironmentPassBlock block{};
  const double rotation = environment.rotationDeg() * kPi / 180.0;
  block.params = glm::vec4(static_cast<float>(std::cos(rotation)), static_cast<float>(std::sin(rotation)),
                           environment.intensity(), 0.0f);
  if (environment.isSky()) {
    const SkyParams& sky = environment.skyParams();
    const double radius = sky.sunAngularRadiusDeg * kPi / 180.0;
    const double rendered = std::max(radius, 2.0 / faceSize);
    // Same energy: radiance times the disc's solid angle 2 pi (1 - cos r) stays put.
    const double scale = (1.0 - std::cos(radius)) / (1.0 - std::cos(rendered));
    block.sunDirection = glm::vec4(glm::normalize(sky.sunDirection), static_cast<float>(rendered));
    block.sunRadiance = glm::vec4(sky.sunRadiance * static_cast<float>(scale), 0.0f);
    block.zenith = glm::vec4(sky.zenith, 0.0f);
    block.horizon = glm::vec4(sky.horizon, 0.0f);
    block.ground = glm::vec4(sky.ground, 0.0f);
    block.sizes = glm::ivec4(faceSize, kSkySubsamples, 0, 0);
  } else {
    // Enough subsamples that a cube texel at a face centre sees every equirectangular column (4 faces span them).
    const int width = environment.equirect().width;
    const int subsamples = std::clamp((width + 4 * faceSize - 1) / (4 * faceSize), 1, kMaxSubsamples);
    block.sizes = glm::ivec4(faceSize, subsamples, 0, 0);
  }
  return block;
}

}  // namespace

EnvironmentCubemapPass::EnvironmentCubemapPass(const ShaderLibrary& shaders)
    : equirectProgram_(shaders.compute("ibl/environment_cubemap.comp", {{"SOURCE_SKY", "0"}})),
      skyProgram_(shaders.compute("ibl/environment_cubemap.comp", {{"SOURCE_SKY", "1"}})) {}

Cubemap EnvironmentCubemapPass::run(const Environment& environment, int faceSize) const {
  if (faceSize < 1) throw std::invalid_argument("environment cube map face size must be >= 1");
  Cubemap cubemap("ibl.environment", GL_RGBA16F, faceSize, mipLevelCount(faceSize, faceSize));
  const UniformBuffer<EnvironmentPassBlock> block("ibl.environment.block", passBlock(environment, faceSize));
  block.bind(0);

  // Linear filtering, wrapping around in longitude; the sampler object overrides the texture's own state.
  const Sampler equirectSampler("ibl.equirect.sampler", GL_REPEAT, GL_CLAMP_TO_EDGE, GL_LINEAR, GL_LINEAR);
  std::optional<Texture> equirect;
  if (environment.isSky()) {
    skyProgram_.use();
  } else {
    const ImageRgbaF& image = environment.equirect();
    // Float32: real suns exceed the half-float range before the intensity scales them.
    equirect.emplace("ibl.equirect", GL_RGBA32F, image.width, image.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(equirect->id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT, image.pixels.data());
    glBindTextureUnit(0, equirect->id());
    glBindSampler(0, equirectSampler.id());
    equirectProgram_.use();
  }
  glBindImageTexture(0, cubemap.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  const GLuint groups = (static_cast<GLuint>(faceSize) + kGroupSize - 1) / kGroupSize;
  glDispatchCompute(groups, groups, 6);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glGenerateTextureMipmap(cubemap.id());
  glBindSampler(0, 0);
  glUseProgram(0);
  checkGlError("EnvironmentCubemapPass::run");
  return cubemap;
}

}  // namespace pbr
