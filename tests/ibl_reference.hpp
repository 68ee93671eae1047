#pragma once
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "ibl/cubemap.hpp"
#include "ibl/irradiance_sh.hpp"

namespace pbr::test {

// Double-precision references for the IBL tests, written from the GL specification and the papers rather than
// from the shaders.

constexpr double kPi = 3.14159265358979323846;

// Texels of a cube-map level as GL returns them: index (face * size + y) * size + x, y along t.
std::vector<glm::vec4> readCubemapLevel(const Cubemap& cubemap, int level);

// The face and (s, t) in [0, 1]^2 that GL samples for direction d (GL 4.5 core spec, table 8.19).
struct CubeCoord {
  int face;
  glm::dvec2 st;
};
CubeCoord cubeCoord(const glm::dvec3& d);

// The unit direction through the centre of texel (x, y) of `face`: table 8.19 solved for the direction.
glm::dvec3 cubeTexelDirection(int face, int x, int y, int size);

// Exact solid angle of texel (x, y) of a face of `size` texels: the integral of the face's area element
// dx dy / (1 + x^2 + y^2)^(3/2), whose antiderivative is atan(x y / sqrt(1 + x^2 + y^2)).
double cubeTexelSolidAngle(int x, int y, int size);

// One cube-map level in double: radiance (rgb), unit direction and solid angle per texel.
struct CubeTexels {
  int size = 0;
  std::vector<glm::dvec3> radiance;
  std::vector<glm::dvec3> direction;
  std::vector<double> solidAngle;
};
CubeTexels cubeTexels(const Cubemap& cubemap, int level);

// Sum of radiance x solid angle over all texels: the energy the level holds.
glm::dvec3 totalEnergy(const CubeTexels& texels);

// E(n) = sum over texels of L max(n.w, 0) dw: irradiance by brute force, the reference for the diffuse term.
glm::dvec3 bruteForceIrradiance(const CubeTexels& texels, const glm::dvec3& n);

// n points spread evenly over the sphere (the spherical Fibonacci lattice).
std::vector<glm::dvec3> fibonacciSphere(int n);

// Reads the coefficients IrradianceShPass wrote.
IblBlock readIblBlock(const Buffer& buffer);

// Reads an RG16F table as (x, y) per texel, rows from y = 0.
std::vector<glm::vec2> readDfgTable(const Texture& table);

// The GGX distribution D(h) in terms of cos theta_h (Walter et al. 2007, eq. 33).
double ggxD(double cosThetaH, double a);
// Height-correlated Smith G2 / (4 n.l n.v), from Lambda(t) = (sqrt(1 + a^2 tan^2 t) - 1) / 2 (Heitz 2014,
// "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs").
double smithVisibility(double NoV, double NoL, double a);
// The renderer's alpha for a perceptual roughness: max(r, 0.045)^2 (lighting/brdf.glsl).
double alphaFromRoughness(double roughness);

// (A, B) of the split sum by quadrature over the half vector in double: F0 A + B = integral of
// D V F n.l dl with Schlick's F.
glm::dvec2 referenceDfg(double NoV, double roughness);

}  // namespace pbr::test
