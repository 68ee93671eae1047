#version 450 core
// Shadow casters' depth from a light (pbr::GBufferPass::renderDepth): positions through the view-projection of one
// of the light's views; with ALPHA_MASK the base colour's UVs (the second set with UV1, where the map reads it) and
// the vertex colours' alpha (VERTEX_COLORS) for the cut-out. A draw covers a run of the light's views, instance i
// drawing view firstView + i; with VIEWPORT_FROM_VERTEX (GL_ARB_shader_viewport_layer_array) into viewport
// firstView + i, which holds that view's square, so that one draw serves a caster's views of one light; without it
// each draw is one view, into viewport 0.
#if VIEWPORT_FROM_VERTEX
#extension GL_ARB_shader_viewport_layer_array : require
#endif
#include "object.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
#if ALPHA_MASK && UV1
layout(location = 5) in vec2 inUv1;
#endif
#if ALPHA_MASK && VERTEX_COLORS
layout(location = 4) in vec4 inColor;
#endif

// The light's views, at most 16 (GL's least number of viewports), as pbr::GBufferPass::renderDepth packs them.
layout(std140, binding = SHADOW_VIEWS_UBO) uniform ShadowViews { mat4 viewProjections[16]; };
layout(location = 0) uniform uint firstView;

#if ALPHA_MASK
layout(location = 1) out vec2 vUv;
#endif
#if ALPHA_MASK && VERTEX_COLORS
layout(location = 2) out float vAlpha;
#endif

void main() {
#if ALPHA_MASK && UV1
  vUv = ((uint(object.orientation.y) >> uint(BASE_COLOR_MAP_UNIT)) & 1u) != 0u ? inUv1 : inUv;
#elif ALPHA_MASK
  vUv = inUv;
#endif
#if ALPHA_MASK && VERTEX_COLORS
  vAlpha = inColor.a;
#endif
  uint view = firstView + uint(gl_InstanceID);
#if VIEWPORT_FROM_VERTEX
  gl_ViewportIndex = int(view);
#endif
  gl_Position = viewProjections[view] * (object.model * vec4(inPosition, 1.0));
}
