#pragma once
#include <glm/vec3.hpp>

#include "core/scene/scene.hpp"

// An incident-light meter for scenes that bring lights in physical units (lm, cd, lux) and no exposure: what a
// photographer standing at the subject would read, turned into the EV100 a camera would be set to.
namespace pbr {

// Illuminance at `point` in lux from the scene's lights as a spherical receptor sees it (each light's full
// illuminance, no cosine): point and spot lights I / d^2 through their distance window and cone, directional
// lights E, each weighted by the luminance of its colour. A light nearer than `nearest` counts as if at that
// distance, so one placed on or inside a model does not dominate the reading; its window is taken at the distance
// left to that sphere, so a light reaching the model but not the point still counts.
double incidentIlluminance(const Scene& scene, const glm::vec3& point, float nearest);

// ISO 2720: an incident-light meter sets EV100 = log2(E S / C) for illuminance E, ISO S = 100 and the flat-receptor
// calibration constant C = 250 lx s, so that a white Lambert surface under E shows 250 / (120 pi) = 0.66 after
// exposureFromEv100.
double ev100FromIlluminance(double lux);

}  // namespace pbr
