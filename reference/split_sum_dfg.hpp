#pragma once
#include <glm/vec2.hpp>

namespace pbr::reference {

// (A, B) of the split sum (Karis 2013, "Real Shading in Unreal Engine 4") for GGX with exact height-correlated
// Smith visibility and Schlick's Fresnel, F0 A + B = integral of D V F n.l dl, by quadrature over the half vector
// in double: the values the renderer's DFG table approximates. Perceptual roughness, clamped like the renderer's.
glm::dvec2 splitSumDfg(double NoV, double roughness);

}  // namespace pbr::reference
