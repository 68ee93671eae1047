// The heat-map ramp of the debug images, t in [0, 1]: black -> blue -> cyan -> green -> yellow -> red, ordered and
// readable in grey scale too. No colour on it has r = g = b but black, so grey marks pixels without data.
vec3 heat(float t) {
  const vec3 stops[6] = vec3[6](vec3(0.0), vec3(0.0, 0.1, 0.9), vec3(0.0, 0.8, 0.9), vec3(0.1, 0.85, 0.1),
                                vec3(1.0, 0.9, 0.0), vec3(1.0, 0.05, 0.0));
  float x = clamp(t, 0.0, 1.0) * 5.0;
  int i = min(int(x), 4);
  return mix(stops[i], stops[i + 1], x - float(i));
}
