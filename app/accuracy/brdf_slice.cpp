#include "app/accuracy/brdf_slice.hpp"

#include <cmath>

#include <glm/vec4.hpp>

#include "lighting/brdf_grid.hpp"
#include "reference/reference_brdf.hpp"

namespace pbr {

BrdfSlice computeBrdfSlice(const ShaderLibrary& shaders, const ShadingVariant& variant, const SliceMaterial& material,
                           int angles, int roughnesses) {
  const std::vector<glm::vec4> gpu =
      evaluateBrdfGrid(shaders, variant, material.baseColor, material.metalness, angles, roughnesses);
  const size_t cells = size_t(angles) * roughnesses;

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
