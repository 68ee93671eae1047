#include "gbuffer/gbuffer_pass.hpp"

#include <cstring>

#include <glm/matrix.hpp>

#include "core/bindings.hpp"
#include "gbuffer/object_block.hpp"

namespace pbr {

namespace {

GLsizeiptr alignedStride() {
  GLint align = 256;
  glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &align);
  const GLsizeiptr a = align > 0 ? align : 256;
  return (static_cast<GLsizeiptr>(sizeof(ObjectBlock)) + a - 1) / a * a;
}

std::vector<unsigned char> packObjectBlocks(const Scene& scene, GLsizeiptr stride) {
  std::vector<unsigned char> bytes(static_cast<size_t>(stride) * scene.objects.size());
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    ObjectBlock b{};
    b.model = o.transform;
    b.normalMatrix = glm::transpose(glm::inverse(o.transform));
    b.baseColor = glm::vec4(o.material.baseColor, 1.0f);
    b.material = glm::vec4(o.material.roughness, o.material.metalness, 0.0f, 0.0f);
    std::memcpy(&bytes[i * static_cast<size_t>(stride)], &b, sizeof b);
  }
  return bytes;
}

}  // namespace

GBufferPass::GBufferPass(const ShaderLibrary& shaders, const Scene& scene)
    : program_(shaders.graphics("gbuffer/gbuffer.vert", "gbuffer/gbuffer.frag")),
      blockStride_(alignedStride()),
      objectBlocks_(static_cast<size_t>(blockStride_) * scene.objects.size(), packObjectBlocks(scene, blockStride_).data(), 0) {
  meshes_.reserve(scene.meshes.size());
  for (const MeshData& m : scene.meshes) meshes_.emplace_back(m);
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    draws_.push_back({scene.objects[i].mesh, static_cast<GLintptr>(i) * blockStride_});
  }
}

void GBufferPass::render(const GBuffer& target, const UniformBuffer<FrameBlock>& frame) const {
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
  glViewport(0, 0, target.width, target.height);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glEnable(GL_FRAMEBUFFER_SRGB);
  const float zeros[4] = {0, 0, 0, 0};
  const float farDepth = 0.0f;
  for (int i = 0; i < 3; ++i) glClearNamedFramebufferfv(target.framebuffer.id(), GL_COLOR, i, zeros);
  glClearNamedFramebufferfv(target.framebuffer.id(), GL_DEPTH, 0, &farDepth);

  program_.use();
  frame.bind(binding::kFrameUbo);
  for (const Draw& d : draws_) {
    glBindBufferRange(GL_UNIFORM_BUFFER, binding::kObjectUbo, objectBlocks_.id(), d.blockOffset, sizeof(ObjectBlock));
    meshes_[static_cast<size_t>(d.mesh)].draw();
  }
  glDisable(GL_FRAMEBUFFER_SRGB);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace pbr
