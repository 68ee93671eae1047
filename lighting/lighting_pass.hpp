#pragma once
#include <map>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/frame_block.hpp"
#include "core/shader_library.hpp"
#include "core/uniform_buffer.hpp"
#include "lighting/light_buffer.hpp"
#include "lighting/shading_model.hpp"

namespace pbr {

// std140 mirror of `LightingBlock` in shaders/lighting/lights.glsl.
struct LightingBlock {
  glm::vec4 ambient;
  glm::uvec4 counts;  // x: lights in the frame
};
static_assert(sizeof(LightingBlock) == 32, "LightingBlock must match its std140 layout");

// The G-buffer channels the lighting pass reads, as plain textures: lighting knows no geometry pass.
struct SurfaceTextures {
  const Texture& baseColor;
  const Texture& normal;
  const Texture& material;
  const Texture& depth;
};

struct LightingOptions {
  ShadingModel model = ShadingModel::Pbr;
  Visibility visibility = Visibility::HeightCorrelated;
  glm::vec3 ambient{0.0f};
};

// Deferred lighting in a compute shader; one shader permutation per (model, visibility), compiled on first use.
class LightingPass {
 public:
  explicit LightingPass(const ShaderLibrary& shaders) : shaders_(shaders) {}

  // Brute force: every light for every pixel. The reference the clustered path is tested against.
  void renderBruteForce(const SurfaceTextures& surface, const LightBuffer& lights, const LightingOptions& options,
                        const UniformBuffer<FrameBlock>& frame, const Texture& hdrOut);

 private:
  const Program& program(const LightingOptions& options);

  const ShaderLibrary& shaders_;
  std::map<int, Program> programs_;
  UniformBuffer<LightingBlock> block_;
};

}  // namespace pbr
