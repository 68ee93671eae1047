// Cube map texels and directions in the OpenGL convention (GL 4.5 core spec, section 8.13, table 8.19): layer
// = face in the order +X, -X, +Y, -Y, +Z, -Z; texel (x, y) of a face is at (s, t) = ((x, y) + 0.5) / size, and
// the direction whose major axis picks that face maps to s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2.

// The (unnormalised) direction through face coordinates st in [0, 1]^2: the spec's table inverted.
vec3 cubeDirection(int face, vec2 st) {
  vec2 c = st * 2.0 - 1.0;  // (sc, tc) / |ma|
  switch (face) {
    case 0: return vec3(1.0, -c.y, -c.x);
    case 1: return vec3(-1.0, -c.y, c.x);
    case 2: return vec3(c.x, 1.0, c.y);
    case 3: return vec3(c.x, -1.0, -c.y);
    case 4: return vec3(c.x, -c.y, 1.0);
    default: return vec3(-c.x, -c.y, -1.0);
  }
}

// The unit direction through the centre of texel (x, y) of face z of a level with faces of `size` texels.
vec3 cubeTexelDirection(ivec3 texel, int size) {
  return normalize(cubeDirection(texel.z, (vec2(texel.xy) + 0.5) / float(size)));
}

// Solid angle of the face region [0, x] x [0, y] seen from the centre, in face coordinates [-1, 1]^2 (Driscoll
// 2012, "Cubemap Texel Solid Angle").
float cubeAreaElement(float x, float y) { return atan(x * y, sqrt(x * x + y * y + 1.0)); }

// Exact solid angle of one texel: the areas of its four corners combined, so that the texels sum to 4 pi.
float cubeTexelSolidAngle(ivec2 texel, int size) {
  vec2 lo = vec2(texel) / float(size) * 2.0 - 1.0;
  vec2 hi = vec2(texel + 1) / float(size) * 2.0 - 1.0;
  return cubeAreaElement(lo.x, lo.y) - cubeAreaElement(lo.x, hi.y) - cubeAreaElement(hi.x, lo.y) +
         cubeAreaElement(hi.x, hi.y);
}

// Approximate solid angle of a texel of a level with faces of `size` texels around unit direction d: the
// projected area (2 / size)^2 foreshortened by |ma|^3 (Colbert & Krivanek, GPU Gems 3, ch. 20,
// "Mipmap Filtered Samples": the distortion term).
float cubeTexelSolidAngleAt(vec3 d, int size) {
  float ma = max(max(abs(d.x), abs(d.y)), abs(d.z));
  float texel = 2.0 / float(size);
  return texel * texel * ma * ma * ma;
}
