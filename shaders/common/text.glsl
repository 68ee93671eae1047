// A 3x5 pixel font for the text of debug images (legends): ASCII 32 (space) to 90 ('Z'), capitals only, one bit
// per pixel, rows top first; text is upper-cased before it gets here (pbr::LegendText).
const uint GLYPHS[59] = uint[59](
    0x0000u, 0x2482u, 0x5A00u, 0x5F7Du, 0x3C9Eu, 0x52A5u, 0x2AABu, 0x2400u,
    0x1491u, 0x4494u, 0x0AA8u, 0x05D0u, 0x0014u, 0x01C0u, 0x0002u, 0x12A4u,
    0x7B6Fu, 0x2C97u, 0x73E7u, 0x73CFu, 0x5BC9u, 0x79CFu, 0x79EFu, 0x7249u,
    0x7BEFu, 0x7BCFu, 0x0410u, 0x0414u, 0x1511u, 0x0E38u, 0x4454u, 0x6282u,
    0x2BE3u, 0x2BEDu, 0x6BAEu, 0x3923u, 0x6B6Eu, 0x79A7u, 0x79A4u, 0x396Bu,
    0x5BEDu, 0x7497u, 0x126Au, 0x5BADu, 0x4927u, 0x5FEDu, 0x6B6Du, 0x2B6Au,
    0x6BA4u, 0x2B73u, 0x6BADu, 0x388Eu, 0x7492u, 0x5B6Fu, 0x5B6Au, 0x5BFDu,
    0x5AADu, 0x5A92u, 0x72A7u);
const int GLYPH_ADVANCE = 4;  // font pixels from one character to the next: 3 wide and a gap

// Whether pixel p (y down) is set in the glyph of ASCII character `c` drawn at `origin` with `scale` pixels per
// font pixel; characters outside the font draw nothing.
bool glyphPixel(uint c, ivec2 origin, int scale, ivec2 p) {
  ivec2 q = (p - origin) / scale;
  if (any(lessThan(p, origin)) || q.x >= 3 || q.y >= 5 || c < 32u || c > 90u) return false;
  return ((GLYPHS[c - 32u] >> uint(14 - (q.y * 3 + q.x))) & 1u) != 0u;
}

uint decimalDigits(uint value) {
  uint digits = 1u;
  for (uint v = value; v >= 10u; v /= 10u) ++digits;
  return digits;
}

// Whether pixel p lies on the decimal digits of `value`, left-aligned at `origin`; each digit advances
// GLYPH_ADVANCE * scale.
bool numberPixel(uint value, ivec2 origin, int scale, ivec2 p) {
  uint digits = decimalDigits(value);
  int advance = GLYPH_ADVANCE * scale;
  int i = (p.x - origin.x) / advance;
  if (p.x < origin.x || i >= int(digits)) return false;
  uint d = value;
  for (int k = int(digits) - 1; k > i; --k) d /= 10u;
  return glyphPixel(48u + d % 10u, origin + ivec2(i * advance, 0), scale, p);
}
