#include "ibl/dfg_table.hpp"

#include "core/gl/square_table.hpp"

namespace pbr {

DfgTablePass::DfgTablePass(const ShaderLibrary& shaders) : program_(shaders.compute("ibl/dfg.comp")) {}

Texture DfgTablePass::run(int size, int samples) const {
  return computeSquareTable("ibl.dfg", program_, GL_RG16F, size, samples);
}

}  // namespace pbr
