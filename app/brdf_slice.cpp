#include "app/brdf_slice.hpp"

#include <cmath>

#include <glm/vec4.hpp>

#include "reference/reference_brdf.hpp"

namespace pbr {

BrdfSlice computeBrdfSlice(const ShaderLibrary& shaders, const ShadingVariant& variant, const SliceMaterial& material,
                           int angles, int roughnesses) {
  const Program program = shaders.compute("accuracy/brdf_slice.comp", shaderDefines(variant));
  const size_t cells = size_t(angles) * roughnesses;
  Buffer values(cells * sizeof(glm::vec4), nullptr, 0);
  program.use();
  glProgramUniform2ui(program.id(), 0, GLuint(angles), GLuint(roughnesses));
  glProgramUniform4f(program.id(), 1, material.baseColor.x, material.baseColor.y, material.baseColor.z,
                     material.metalness);
  values.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  glDispatchCompute(GLuint(angles + 7) / 8, GLuint(roughnesses + 7) / 8, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> gpu(cells);
  glGetNamedBufferSubData(values.id(), 0, GLsizeiptr(cells * sizeof(glm::vec4)), gpu.data());

  constexpr double kHalfPi = 1.57079632679489661923;
  BrdfSlice slice{angles, roughnesses, std::vector<float>(cells)};
  reference::ReferenceMaterial m;
  m.baseColor = glm::dvec3(material.baseColor);
  m.metalness = material.metalness;
  for (int r = 0; r < roughnesses; ++r) {
    m.roughness = (r + 0.5) / roughnesses;
    for (int a = 0; a < angles; ++a) {
      // The same float angle the shader computed, so both evaluate the same directions.
      const double theta = double(float((a + 0.5) / angles * kHalfPi));
      const glm::dvec3 N(0.0, 0.0, 1.0), V(std::sin(theta), 0.0, std::cos(theta)), L(-V.x, 0.0, V.z);
      const glm::dvec3 f = reference::evaluateBrdf(N, V, L, m).sum();
      const double ref = f.x + f.y + f.z;
      const glm::vec4& g = gpu[size_t(r) * angles + a];
      slice.relativeError[size_t(r) * angles + a] = float(std::abs(double(g.x) + g.y + g.z - ref) / ref);
    }
  }
  return slice;
}

}  // namespace pbr
