#pragma once
#include "core/scene/binding_table.hpp"

namespace pbr {

// The binding points of the lighting module's passes (deferred lighting, cluster assignment, debug views), one
// table for C++ and GLSL: programs are compiled with lightingBindingDefines().
namespace lighting_binding {
constexpr BindingPoint kLightingUbo{"LIGHTING_UBO", BindingKind::UniformBuffer, 2};
constexpr BindingPoint kClusterUbo{"CLUSTER_UBO", BindingKind::UniformBuffer, 4};
constexpr BindingPoint kLightWindowUbo{"LIGHT_WINDOW_UBO", BindingKind::UniformBuffer, 6};
constexpr BindingPoint kDirectionalLightUbo{"DIRECTIONAL_LIGHT_UBO", BindingKind::UniformBuffer, 7};
constexpr BindingPoint kSpotWindowUbo{"SPOT_WINDOW_UBO", BindingKind::UniformBuffer, 8};
constexpr BindingPoint kLegendUbo{"LEGEND_UBO", BindingKind::UniformBuffer, 9};  // debug views' legend text
constexpr BindingPoint kLightSsbo{"LIGHT_SSBO", BindingKind::StorageBuffer, 0};
constexpr BindingPoint kClusterSsbo{"CLUSTER_SSBO", BindingKind::StorageBuffer, 1};
constexpr BindingPoint kLightIndexSsbo{"LIGHT_INDEX_SSBO", BindingKind::StorageBuffer, 2};
constexpr BindingPoint kLightVisibleSsbo{"LIGHT_VISIBLE_SSBO", BindingKind::StorageBuffer, 3};
constexpr BindingPoint kSpotConeSsbo{"SPOT_CONE_SSBO", BindingKind::StorageBuffer, 4};
constexpr BindingPoint kClusterStatusSsbo{"CLUSTER_STATUS_SSBO", BindingKind::StorageBuffer, 5};
constexpr BindingPoint kLightingStatsSsbo{"LIGHTING_STATS_SSBO", BindingKind::StorageBuffer, 6};
constexpr BindingPoint kClusterBoxesSsbo{"CLUSTER_BOXES_SSBO", BindingKind::StorageBuffer, 7};
constexpr BindingPoint kClusterSlotsSsbo{"CLUSTER_SLOTS_SSBO", BindingKind::StorageBuffer, 8};
constexpr BindingPoint kSlotClustersSsbo{"SLOT_CLUSTERS_SSBO", BindingKind::StorageBuffer, 9};
constexpr BindingPoint kClusterOccupancySsbo{"CLUSTER_OCCUPANCY_SSBO", BindingKind::StorageBuffer, 10};
constexpr BindingPoint kClusterCursorSsbo{"CLUSTER_CURSOR_SSBO", BindingKind::StorageBuffer, 11};
constexpr BindingPoint kSlotMasksSsbo{"SLOT_MASKS_SSBO", BindingKind::StorageBuffer, 12};
constexpr BindingPoint kBigLightsSsbo{"BIG_LIGHTS_SSBO", BindingKind::StorageBuffer, 13};
constexpr BindingPoint kSlotMasksHighSsbo{"SLOT_MASKS_HIGH_SSBO", BindingKind::StorageBuffer, 14};
// The occupied clusters compacted for the CPU's read-back (cluster_compact.comp).
constexpr BindingPoint kOccupiedClustersSsbo{"OCCUPIED_CLUSTERS_SSBO", BindingKind::StorageBuffer, 20};
// The planar casters' planes the occupancy pass tests visible points against, and the sides it finds them on
// (cluster_occupancy.glsl, LightClusters::setCasterPlanes).
constexpr BindingPoint kCasterPlanesUbo{"CASTER_PLANES_UBO", BindingKind::UniformBuffer, 11};
constexpr BindingPoint kPlaneSidesSsbo{"PLANE_SIDES_SSBO", BindingKind::StorageBuffer, 23};
// The lighting pass's tiles, sorted into those holding a surface and the others (surface_tiles.comp).
constexpr BindingPoint kSurfaceTilesSsbo{"SURFACE_TILES_SSBO", BindingKind::StorageBuffer, 21};
// The G-buffer channels as shaders/lighting/surface.glsl samples them.
constexpr BindingPoint kBaseColorUnit{"SURFACE_BASE_COLOR_UNIT", BindingKind::TextureUnit, 0};
constexpr BindingPoint kNormalUnit{"SURFACE_NORMAL_UNIT", BindingKind::TextureUnit, 1};
constexpr BindingPoint kMaterialUnit{"SURFACE_MATERIAL_UNIT", BindingKind::TextureUnit, 2};
constexpr BindingPoint kDepthUnit{"SURFACE_DEPTH_UNIT", BindingKind::TextureUnit, 3};
constexpr BindingPoint kSpecularUnit{"SURFACE_SPECULAR_UNIT", BindingKind::TextureUnit, 6};
constexpr BindingPoint kClearcoatUnit{"SURFACE_CLEARCOAT_UNIT", BindingKind::TextureUnit, 7};
constexpr BindingPoint kSheenUnit{"SURFACE_SHEEN_UNIT", BindingKind::TextureUnit, 14};
// The lighting pass's radiance target, and its running sum over light chunks (LightingPass::render).
constexpr BindingPoint kRadianceImage{"RADIANCE_IMAGE", BindingKind::ImageUnit, 0};
constexpr BindingPoint kPartialRadianceImage{"PARTIAL_RADIANCE_IMAGE", BindingKind::ImageUnit, 1};
// Per-pixel light-pixel pair counts, written by the lighting pass and read by the efficiency debug view.
constexpr BindingPoint kPairCountImage{"PAIR_COUNT_IMAGE", BindingKind::ImageUnit, 2};
// Per-pixel luminance from casting lights with and without their shadows, written by the lighting pass and read by
// the shadows debug view with the atlas's depth and its squares' owners.
constexpr BindingPoint kShadowLightImage{"SHADOW_LIGHT_IMAGE_UNIT", BindingKind::ImageUnit, 3};
constexpr BindingPoint kShadowDepthUnit{"SHADOW_DEPTH_UNIT", BindingKind::TextureUnit, 12};
constexpr BindingPoint kShadowOwnerUnit{"SHADOW_OWNER_UNIT", BindingKind::TextureUnit, 13};
// Weighted blended order-independent transparency's sums, read by its composite pass (OitTargets).
constexpr BindingPoint kOitAccumulationUnit{"OIT_ACCUMULATION_UNIT", BindingKind::TextureUnit, 4};
constexpr BindingPoint kOitRevealageUnit{"OIT_REVEALAGE_UNIT", BindingKind::TextureUnit, 5};
// Exact order-independent transparency's per-pixel lists (OitTargets).
constexpr BindingPoint kLayerNodeSsbo{"LAYER_NODE_SSBO", BindingKind::StorageBuffer, 18};
// The PBR lighting pass's directional-albedo table for uniform ambient light (lighting/ambient_albedo.hpp).
constexpr BindingPoint kAmbientAlbedoUnit{"AMBIENT_ALBEDO_UNIT", BindingKind::TextureUnit, 10};
// KHR_materials_sheen's albedo table (lighting/ambient_albedo.hpp's SheenAlbedoTable).
constexpr BindingPoint kSheenAlbedoUnit{"SHEEN_ALBEDO_UNIT", BindingKind::TextureUnit, 15};
// The opaque frame transmissive surfaces see through, with its mip chain (TransmissionTargets); past the sixteen
// units the other programs share (GL 4.5 has at least 80 in all, 16 a stage).
constexpr BindingPoint kTransmissionBackgroundUnit{"TRANSMISSION_BACKGROUND_UNIT", BindingKind::TextureUnit, 16};
}  // namespace lighting_binding

// Where shaders/lighting/brdf_grid.comp writes its values (evaluateBrdfGrid, brdf_grid.hpp), a program run alone.
constexpr BindingPoint kBrdfGridSsbo{"BRDF_GRID_SSBO", BindingKind::StorageBuffer, 0};

// The frame block's, the lighting module's, the environment maps' and the shadow maps' points: everything bound
// while the lighting module's programs run.
ShaderDefines lightingBindingDefines();
// The points of the programs drawn with the geometry pass's vertex shader (BlendedSurfaces), the geometry pass's
// `geometry` points (object block, material maps) with those of the lighting module they read: the forward
// lighting's (forward.frag), or the clusters' occupancy's (cluster_occupancy.frag). Throws std::logic_error where
// the two tables overlap.
ShaderDefines forwardBindingDefines(const std::vector<BindingPoint>& geometry);
ShaderDefines occupancyBindingDefines(const std::vector<BindingPoint>& geometry);

}  // namespace pbr
