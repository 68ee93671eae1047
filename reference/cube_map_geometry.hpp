#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace pbr::reference {

// Cube-map geometry in double, from the GL 4.5 core specification (table 8.19) rather than from the shaders.

// The face (GL order +X, -X, +Y, -Y, +Z, -Z) and (s, t) in [0, 1]^2 that GL samples for direction d.
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

}  // namespace pbr::reference
