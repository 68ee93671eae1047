#include "lighting/brdf_grid.hpp"

#include "core/gl/gl_objects.hpp"
#include "lighting/lighting_bindings.hpp"

namespace pbr {

std::vector<glm::vec4> evaluateBrdfGrid(const ShaderLibrary& shaders, const ShadingVariant& variant,
                                        const glm::vec3& baseColor, float metalness, int angles, int roughnesses) {
  const Program program =
      shaders.compute("lighting/brdf_grid.comp", concat(shaderDefines(variant), bindingDefines({kBrdfGridSsbo})));
  const size_t cells = size_t(angles) * roughnesses;
  Buffer values("brdfGrid.values", cells * sizeof(glm::vec4), nullptr, 0);
  program.use();
  // Uniform locations 0 and 1 of brdf_grid.comp.
  glProgramUniform2ui(program.id(), 0, GLuint(angles), GLuint(roughnesses));
  glProgramUniform4f(program.id(), 1, baseColor.x, baseColor.y, baseColor.z, metalness);
  values.bindBase(GL_SHADER_STORAGE_BUFFER, kBrdfGridSsbo.index);
  glDispatchCompute(GLuint(angles + 7) / 8, GLuint(roughnesses + 7) / 8, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> out(cells);
  glGetNamedBufferSubData(values.id(), 0, GLsizeiptr(cells * sizeof(glm::vec4)), out.data());
  return out;
}

}  // namespace pbr
