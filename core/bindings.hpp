#pragma once
// Binding points shared by C++ and GLSL; shaders/common/bindings.glsl mirrors these numbers.
namespace pbr::binding {
constexpr unsigned kFrameUbo = 0;
constexpr unsigned kObjectUbo = 1;
constexpr unsigned kLightingUbo = 2;
constexpr unsigned kPostUbo = 3;
constexpr unsigned kClusterUbo = 4;
constexpr unsigned kLightSsbo = 0;
constexpr unsigned kClusterSsbo = 1;
constexpr unsigned kLightIndexSsbo = 2;
constexpr unsigned kLightVisibleSsbo = 3;
constexpr unsigned kClusterBoundsSsbo = 4;
constexpr unsigned kClusterStatusSsbo = 5;
constexpr unsigned kLightingStatsSsbo = 6;
constexpr unsigned kClusterViewLightsSsbo = 7;
constexpr unsigned kClusterTileMasksSsbo = 8;
// Texture units of the G-buffer pass's material maps.
constexpr unsigned kBaseColorMapUnit = 0;
constexpr unsigned kMetallicRoughnessMapUnit = 1;
constexpr unsigned kNormalMapUnit = 2;
constexpr unsigned kOcclusionMapUnit = 3;
constexpr unsigned kEmissiveMapUnit = 4;
// Image-based lighting (ibl/, shaders/ibl/ibl_sample.glsl); its units clear the G-buffer and material units 0-4.
constexpr unsigned kIblUbo = 5;
constexpr unsigned kIblSpecularUnit = 8;
constexpr unsigned kIblDfgUnit = 9;
// The PBR lighting pass's directional-albedo table for uniform ambient light (lighting/ambient_albedo.hpp).
constexpr unsigned kAmbientAlbedoUnit = 10;
}  // namespace pbr::binding
