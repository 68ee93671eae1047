#include "tests/glsl_probe.hpp"

#include "lighting/lighting_bindings.hpp"

#include <stdexcept>

namespace pbr::test {

namespace {

constexpr GLuint kLocalSize = 64;
// GL 4.3 guarantees only this many work groups per dimension.
constexpr size_t kMaxGroups = 65535;

std::string probeShader(const std::string& source) {
  // The harness follows the snippet so that `probe` is declared before main uses it.
  return "#version 450\n" + source +
         "\n"
         "layout(local_size_x = " + std::to_string(kLocalSize) + ") in;\n"
         "layout(std430, binding = " + std::to_string(GlslProbe::kInputBinding) + ") readonly buffer ProbeInput {\n"
         "  vec4 probeInput[];\n"
         "};\n"
         "layout(std430, binding = " + std::to_string(GlslProbe::kOutputBinding) + ") writeonly buffer ProbeOutput {\n"
         "  vec4 probeOutput[];\n"
         "};\n"
         "void main() {\n"
         "  uint i = gl_GlobalInvocationID.x;\n"
         "  if (i < uint(probeInput.length())) probeOutput[i] = probe(probeInput[i]);\n"
         "}\n";
}

}  // namespace

GlslProbe::GlslProbe(const std::string& name, const std::string& source, const ShaderDefines& defines)
    : program_(ShaderLibrary().computeFromSource(name, probeShader(source), concat(defines, lightingBindingDefines()))) {}

std::vector<glm::vec4> GlslProbe::run(const std::vector<glm::vec4>& input) const {
  std::vector<glm::vec4> output(input.size());
  if (input.empty()) return output;
  const size_t groups = (input.size() + kLocalSize - 1) / kLocalSize;
  if (groups > kMaxGroups) throw std::length_error("GlslProbe: too many elements for one dispatch");

  const size_t bytes = input.size() * sizeof(glm::vec4);
  const Buffer in("glslProbe.in", bytes, input.data(), 0);
  const Buffer out("glslProbe.out", bytes, nullptr, 0);
  in.bindBase(GL_SHADER_STORAGE_BUFFER, kInputBinding);
  out.bindBase(GL_SHADER_STORAGE_BUFFER, kOutputBinding);
  program_.use();
  glDispatchCompute(static_cast<GLuint>(groups), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(out.id(), 0, static_cast<GLsizeiptr>(bytes), output.data());
  glUseProgram(0);
  checkGlError("GlslProbe::run");
  return output;
}

}  // namespace pbr::test
