#pragma once
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace pbr::reference {

// Integrals over an environment given as one cube-map level, summed texel by texel in double: the values the
// renderer's IBL precomputation approximates.

// One cube-map level: radiance (rgb), unit direction and solid angle per texel.
struct CubeTexels {
  int size = 0;
  std::vector<glm::dvec3> radiance;
  std::vector<glm::dvec3> direction;
  std::vector<double> solidAngle;
};
// From texels in the order GL returns them: index (face * size + y) * size + x, y along t.
CubeTexels cubeTexels(const std::vector<glm::vec4>& texels, int size);

// Sum of radiance x solid angle over all texels: the energy the level holds.
glm::dvec3 totalEnergy(const CubeTexels& texels);

// E(n) = sum over texels of L max(n.w, 0) dw: irradiance by brute force, the reference for the diffuse term.
glm::dvec3 bruteForceIrradiance(const CubeTexels& texels, const glm::dvec3& n);

// The environment weighted by KHR_materials_sheen's Charlie lobe about n under the split-sum assumption (V = n):
// sum of L w dw over sum of w dw, w = D(n.h) V(1, n.l) n.l with the extension's D and V (reference_brdf.hpp), the
// reference for the sheen's prefiltered cube map.
glm::dvec3 bruteForceSheen(const CubeTexels& texels, const glm::dvec3& n, double sheenRoughness);

// n points spread evenly over the sphere (the spherical Fibonacci lattice): the normals integrals are compared at.
std::vector<glm::dvec3> fibonacciSphere(int n);

}  // namespace pbr::reference
