#version 450 core
// Second pass of the spherical-harmonic projection (sh_project.comp): invocation k adds coefficient k of every
// block's partial sums and writes it in the layout of IblBlock (ibl_sample.glsl), so that the same buffer serves
// the lighting pass as its uniform block. A few thousand additions each: not worth a parallel reduction.
layout(local_size_x = 9) in;

layout(std430, binding = 0) readonly buffer Partials { vec4 partials[]; };
layout(std430, binding = 1) writeonly buffer Coefficients { vec4 coefficients[9]; };

void main() {
  uint k = gl_LocalInvocationIndex;
  uint blocks = uint(partials.length()) / 9u;
  vec3 sum = vec3(0.0);
  for (uint b = 0u; b < blocks; ++b) sum += partials[b * 9u + k].rgb;
  coefficients[k] = vec4(sum, 0.0);
}
