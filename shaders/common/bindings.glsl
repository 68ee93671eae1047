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
