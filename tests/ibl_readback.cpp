#include "tests/ibl_readback.hpp"

namespace pbr::test {

IblSettings smallIblSettings(int faceSize) {
  IblSettings s;
  s.faceSize = faceSize;
  s.specularLevels = 3;
  s.specularSamples = 16;
  s.dfgSize = 8;
  s.dfgSamples = 16;
  return s;
}

std::vector<glm::vec4> readCubemapLevel(const Cubemap& cubemap, int level) {
  const int size = cubemap.faceSize(level);
  std::vector<glm::vec4> texels(size_t{6} * size * size);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(cubemap.id(), level, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(glm::vec4)),
                    texels.data());
  checkGlError("readCubemapLevel");
  return texels;
}

reference::CubeTexels cubeTexels(const Cubemap& cubemap, int level) {
  return reference::cubeTexels(readCubemapLevel(cubemap, level), cubemap.faceSize(level));
}

IblBlock readIblBlock(const Buffer& buffer) {
  IblBlock block{};
  glGetNamedBufferSubData(buffer.id(), 0, sizeof(IblBlock), &block);
  checkGlError("readIblBlock");
  return block;
}

std::vector<glm::vec2> readDfgTable(const Texture& table) {
  std::vector<glm::vec2> texels(static_cast<size_t>(table.width()) * table.height());
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(table.id(), 0, GL_RG, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(glm::vec2)),
                    texels.data());
  checkGlError("readDfgTable");
  return texels;
}

}  // namespace pbr::test
