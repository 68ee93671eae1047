// Binding points; core/bindings.hpp holds the same numbers for the C++ side.
#define FRAME_UBO 0
#define OBJECT_UBO 1
#define LIGHTING_UBO 2
#define POST_UBO 3
#define CLUSTER_UBO 4
#define LIGHT_SSBO 0
#define CLUSTER_SSBO 1
#define LIGHT_INDEX_SSBO 2
#define LIGHT_VISIBLE_SSBO 3
#define CLUSTER_BOUNDS_SSBO 4
#define CLUSTER_STATUS_SSBO 5
#define LIGHTING_STATS_SSBO 6
#define CLUSTER_VIEW_LIGHTS_SSBO 7
#define CLUSTER_TILE_MASKS_SSBO 8
// Texture units of the G-buffer pass's material maps.
#define BASE_COLOR_MAP_UNIT 0
#define METALLIC_ROUGHNESS_MAP_UNIT 1
#define NORMAL_MAP_UNIT 2
#define OCCLUSION_MAP_UNIT 3
#define EMISSIVE_MAP_UNIT 4
// Image-based lighting (ibl/, shaders/ibl/ibl_sample.glsl); its units clear the G-buffer and material units 0-4.
#define IBL_UBO 5
#define IBL_SPECULAR_UNIT 8
#define IBL_DFG_UNIT 9
// The PBR lighting pass's directional-albedo table for uniform ambient light (lighting/ambient_albedo.hpp).
#define AMBIENT_ALBEDO_UNIT 10
