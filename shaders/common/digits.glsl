// A 3x5 pixel digit font for numbers drawn into debug images (legends), one bit per pixel, rows top first.
const uint DIGIT_GLYPHS[10] = uint[10](0x7B6Fu, 0x2C97u, 0x73E7u, 0x73CFu, 0x5BC9u, 0x79CFu, 0x79EFu, 0x7249u, 0x7BEFu, 0x7BCFu);

// Whether pixel p (y down) is set in the glyph of `digit` drawn at `origin` with `scale` pixels per font pixel.
bool digitPixel(uint digit, ivec2 origin, int scale, ivec2 p) {
  ivec2 q = (p - origin) / scale;
  if (any(lessThan(p, origin)) || q.x >= 3 || q.y >= 5) return false;
  return ((DIGIT_GLYPHS[digit] >> uint(14 - (q.y * 3 + q.x))) & 1u) != 0u;
}

uint decimalDigits(uint value) {
  uint digits = 1u;
  for (uint v = value; v >= 10u; v /= 10u) ++digits;
  return digits;
}

// Whether pixel p lies on the decimal digits of `value`, left-aligned at `origin`; each digit advances 4 * scale.
bool numberPixel(uint value, ivec2 origin, int scale, ivec2 p) {
  uint digits = decimalDigits(value);
  int advance = 4 * scale;
  int i = (p.x - origin.x) / advance;
  if (p.x < origin.x || i >= int(digits)) return false;
  uint d = value;
  for (int k = int(digits) - 1; k > i; --k) d /= 10u;
  return digitPixel(d % 10u, origin + ivec2(i * advance, 0), scale, p);
}
