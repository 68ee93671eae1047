#pragma once
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "ibl/cubemap.hpp"
#include "ibl/ibl_maps.hpp"
#include "ibl/irradiance_sh.hpp"
#include "reference/environment_integrals.hpp"

namespace pbr::test {

// IBL maps small enough for llvmpipe, with faces of `faceSize` texels: a few specular levels and samples and a small
// DFG table, for tests of the terms that do not depend on them (the diffuse term, the sheen's cube).
IblSettings smallIblSettings(int faceSize);

// What the IBL passes wrote, read back from GL for comparison with the double-precision references in reference/.

// Texels of a cube-map level as GL returns them: index (face * size + y) * size + x, y along t.
std::vector<glm::vec4> readCubemapLevel(const Cubemap& cubemap, int level);

// One cube-map level with each texel's direction and solid angle.
reference::CubeTexels cubeTexels(const Cubemap& cubemap, int level);

// Reads the coefficients IrradianceShPass wrote.
IblBlock readIblBlock(const Buffer& buffer);

// Reads an RG16F table as (x, y) per texel, rows from y = 0.
std::vector<glm::vec2> readDfgTable(const Texture& table);

}  // namespace pbr::test
