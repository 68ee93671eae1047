#version 450 core
// Light assignment's first pass for BLEND surfaces: each of their fragments in front of the G-buffer's depth
// occupies its clusters (cluster_occupancy.glsl), so that the forward pass (forward.frag) finds their lights listed.
// Drawn with the geometry pass's vertex stage, no colour written.
#include "cluster_occupancy.glsl"

void main() { occupy(uvec2(gl_FragCoord.xy), gl_FragCoord.z); }
