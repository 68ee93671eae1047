// The procedural sky of pbr::SkyParams: a gradient from the horizon up to the zenith and down to the ground, and
// a sun disc. Reads the EnvironmentPassBlock of environment_cubemap.comp.

vec3 skyGradient(vec3 d) {
  // sqrt brightens towards the horizon the way scattering does, and keeps the colour continuous across it.
  return d.y >= 0.0 ? mix(pass.horizon.rgb, pass.zenith.rgb, sqrt(d.y))
                    : mix(pass.horizon.rgb, pass.ground.rgb, sqrt(-d.y));
}

// Share of a subsample of angular width `subsampleAngle` around d that the sun disc covers: a linear ramp across
// the disc's edge, which measures a straight edge's coverage exactly, so the disc keeps its area.
float sunCoverage(vec3 d, float subsampleAngle) {
  vec3 s = pass.sunDirection.xyz;
  float angle = atan(length(cross(d, s)), dot(d, s));  // exact near 0, where acos(dot) loses its digits
  return clamp((pass.sunDirection.w - angle) / subsampleAngle + 0.5, 0.0, 1.0);
}

vec3 skyRadiance(vec3 d, float subsampleAngle) {
  return skyGradient(d) + pass.sunRadiance.rgb * sunCoverage(d, subsampleAngle);
}
