#pragma once
#include <cstddef>
#include <cstdint>

#include <glm/vec4.hpp>

#include "core/scene/scene.hpp"

namespace pbr {

// std430 (and std140) mirror of `PointLight` in shaders/lighting/lights.glsl.
struct GpuLight {
  glm::vec4 positionRadius;
  glm::vec4 colorIntensity;  // rgb, luminous intensity I = P / (4 pi)
};
static_assert(sizeof(GpuLight) == 32, "GpuLight must match its std430 layout");
static_assert(offsetof(GpuLight, colorIntensity) == 16, "GpuLight must match its std430 layout");

GpuLight toGpuLight(const PointLight& light);

// Mirror of a light's entry in `spotCones` and `windowCones` (shaders/lighting/lights.glsl): the spot light's axis
// times its falloff's scale, and the offset (SpotFalloff); a point light's (0, 0, 0, 1) leaves it unmasked.
using GpuSpotCone = glm::vec4;
GpuSpotCone toGpuSpotCone(const PointLight& light);

// std140 mirror of `DirectionalLightBlock` in shaders/lighting/directional_lights.glsl.
struct GpuDirectionalLight {
  glm::vec4 toLight;           // xyz: unit direction towards the light
  glm::vec4 colorIlluminance;  // rgb, illuminance E in lux
};
// How many are in use is the programs' DIRECTIONAL_LIGHTS define (LightKinds::directional).
struct DirectionalLightBlock {
  GpuDirectionalLight lights[kMaxDirectionalLights];
};
static_assert(sizeof(GpuDirectionalLight) == 32, "GpuDirectionalLight must match its std140 layout");
static_assert(sizeof(DirectionalLightBlock) == 32 * kMaxDirectionalLights, "DirectionalLightBlock: std140");

// The kinds of light a frame has besides point lights (LightBuffer::kinds): each kind's code is compiled only into
// the permutations of frames that have it (SPOT_LIGHTS, DIRECTIONAL_LIGHTS). On llvmpipe even a loop over no light
// runs its body once under an empty lane mask: the directional loop cost `default`'s lighting pass 4-5 ms. The
// directional lights' count is the define itself, so that their loop unrolls and reads each light's entries at a
// constant index, one load for all the pixels of a SIMD row rather than one each: the Blender export's lighting
// pass took 81-84 instead of 89-92 ms on llvmpipe.
struct LightKinds {
  bool spot = false;
  uint32_t directional = 0;  // lights, at most kMaxDirectionalLights
};

// Lights in the largest uniform-buffer window the lighting pass reads (64 KiB, the most llvmpipe and most GPUs
// allow one uniform block). The buffer holds whole windows, so that every window bound is backed in full.
constexpr uint32_t kLightWindowMax = 2048;

}  // namespace pbr
