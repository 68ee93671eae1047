// Spherical harmonics of bands 0-2, in the order Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21, Y22, written in the
// renderer's world axes (the formulas hold in any right-handed frame).

// The real basis functions (Ramamoorthi & Hanrahan 2001, "An Efficient Representation for Irradiance
// Environment Maps", eq. 3).
void shBasis9(vec3 d, out float Y[9]) {
  Y[0] = 0.282095;
  Y[1] = 0.488603 * d.y;
  Y[2] = 0.488603 * d.z;
  Y[3] = 0.488603 * d.x;
  Y[4] = 1.092548 * d.x * d.y;
  Y[5] = 1.092548 * d.y * d.z;
  Y[6] = 0.315392 * (3.0 * d.z * d.z - 1.0);
  Y[7] = 1.092548 * d.x * d.z;
  Y[8] = 0.546274 * (d.x * d.x - d.y * d.y);
}

// Irradiance at normal n from the radiance coefficients L (rgb), the clamped-cosine convolution in closed form
// (Ramamoorthi & Hanrahan 2001, eq. 13).
vec3 shIrradiance9(vec3 n, vec4 L[9]) {
  const float c1 = 0.429043, c2 = 0.511664, c3 = 0.743125, c4 = 0.886227, c5 = 0.247708;
  return c1 * L[8].rgb * (n.x * n.x - n.y * n.y) + c3 * L[6].rgb * n.z * n.z + c4 * L[0].rgb - c5 * L[6].rgb +
         2.0 * c1 * (L[4].rgb * n.x * n.y + L[7].rgb * n.x * n.z + L[5].rgb * n.y * n.z) +
         2.0 * c2 * (L[3].rgb * n.x + L[1].rgb * n.y + L[2].rgb * n.z);
}
