// Mirrors pbr::FrameBlock (core/frame_block.hpp).
layout(std140, binding = FRAME_UBO) uniform FrameBlock {
  mat4 view;
  mat4 projection;
  mat4 viewProjection;
  mat4 inverseView;
  vec4 cameraPosition;
  vec4 viewport;    // width, height, 1/width, 1/height
  vec4 projParams;  // P[0][0], P[1][1], P[2][2], P[3][2]
  vec4 clip;        // near, far
} frame;
