// Mirrors pbr::FrameBlock (core/scene/frame_block.hpp).
layout(std140, binding = FRAME_UBO) uniform FrameBlock {
  mat4 view;
  mat4 projection;
  mat4 viewProjection;
  mat4 inverseView;
  vec4 cameraPosition;
  vec4 viewport;    // width, height, 1/width, 1/height
  vec4 projParams;  // P[0][0], P[1][1], P[2][2], P[3][2]
  vec4 clip;        // near, far, P[2][3], P[3][3]: -1, 0 perspective; 0, 1 orthographic
} frame;

// The view-space z of reversed-Z depth `depth`: clip = P (x, y, z, 1) with w = P23 z + P33 (-z perspective, 1
// orthographic), depth = (P22 z + P32) / w solved for z; exact where the inverse projection would lose digits.
float viewZAt(float depth) {
  return (frame.projParams.w - depth * frame.clip.w) / (depth * frame.clip.z - frame.projParams.z);
}

// The view-space point at pixel p (integer coordinates of its lower-left corner) with reversed-Z depth `depth`.
vec3 viewPositionAt(vec2 p, float depth) {
  vec2 ndc = (p + 0.5) * frame.viewport.zw * 2.0 - 1.0;
  float zView = viewZAt(depth);
  float w = frame.clip.z * zView + frame.clip.w;
  return vec3(w * ndc.x / frame.projParams.x, w * ndc.y / frame.projParams.y, zView);
}

// The view-space direction of the ray through a point of the image (normalized device x, y): from the eye in
// perspective, along the view axis everywhere in orthographic (parallel rays).
vec3 viewRayAt(vec2 ndc) { return vec3(-frame.clip.z * ndc / frame.projParams.xy, -1.0); }

// The world-space direction from `position` towards the viewer: the camera's position in perspective, the
// reversed view axis in orthographic; the other term is multiplied by 0.
vec3 towardsViewer(vec3 position) {
  return (frame.cameraPosition.xyz - position) * -frame.clip.z + frame.inverseView[2].xyz * frame.clip.w;
}
