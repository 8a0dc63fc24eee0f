// Summed-area tables (Crow 1984; Hensley et al. 2005) in 32-bit fixed
// point. Values in [0, 1] are stored as round(v * scale) and summed with
// wrap-around unsigned arithmetic: the four-corner difference of a box is
// exact as long as the box's true sum fits in 32 bits, however large the
// table's own prefix sums grow, so precision does not degrade with the
// map's size (a float table of a 4096^2 map would lose its low bits).

// The table's sum over the texels [0, corner.x) x [0, corner.y) of layer
// `layer` (corner in texel-corner coordinates, clamped to the map; 0 on the
// first row and column).
uvec4 sat_prefix(usampler2DArray sat, int layer, ivec2 corner) {
  corner = min(corner, textureSize(sat, 0).xy);
  if (corner.x <= 0 || corner.y <= 0) return uvec4(0);
  return texelFetch(sat, ivec3(corner - 1, layer), 0);
}

// Average of layer `layer` over the continuous rectangle
// [center - half_width, center + half_width] in texel units (texel (i, j)
// covers [i, i + 1] x [j, j + 1]; the map is constant over each texel),
// cropped to the map: nothing from outside is mixed in, the average is over
// the part inside; half_width > 0. A texel-centred rectangle of half-width
// W + 1/2 is the (2W + 1)^2 box of texels. At other positions and widths
// the texels along the rectangle's edges count with the fraction of them it
// covers, so the average moves continuously with the lookup point and the
// width (Peters et al., "Moment Soft Shadow Mapping", I3D 2016, Sec. 5.1,
// which reads a float table bilinearly; a fixed-point table cannot be
// interpolated before its corners are differenced, so the fractions weight
// whole integer boxes instead).
//
// Along each axis the rectangle touches texels first..last: the first with
// covered length min(first + 1, hi) - lo, the last with hi - last, those
// between them wholly. In 2D that is nine disjoint integer boxes (some
// empty) from sixteen table texels, each differenced in exact wrap-around
// integers and only then converted and weighted by the product of its
// axes' lengths; all weights are positive, so nothing cancels.
vec4 sat_rectangle_average(usampler2DArray sat, int layer, vec2 center, vec2 half_width,
                           float scale) {
  vec2 size = vec2(textureSize(sat, 0).xy);
  center = clamp(center, vec2(0.0), size);  // keeps a part of the rectangle inside
  vec2 lo = clamp(center - half_width, vec2(0.0), size);
  vec2 hi = clamp(center + half_width, vec2(0.0), size);
  ivec2 first = ivec2(floor(lo));
  ivec2 last = max(ivec2(ceil(hi)) - 1, first);
  // Texel-corner coordinates of the table reads: first, first + 1, last,
  // last + 1 along each axis.
  ivec4 xs = ivec4(first.x, first.x + 1, last.x, last.x + 1);
  ivec4 ys = ivec4(first.y, first.y + 1, last.y, last.y + 1);
  uvec4 corner[16];
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) corner[4 * j + i] = sat_prefix(sat, layer, ivec2(xs[i], ys[j]));
  // The three intervals per axis as (start, end) indices into xs / ys: the
  // first texel, the ones between, the last; and their covered lengths (0
  // where an interval is empty or is the first texel again).
  const ivec2 span[3] = ivec2[](ivec2(0, 1), ivec2(1, 2), ivec2(2, 3));
  vec2 first_length = min(vec2(first + 1), hi) - lo;
  vec3 length_x = vec3(first_length.x, last.x > first.x + 1 ? 1.0 : 0.0,
                       last.x > first.x ? hi.x - float(last.x) : 0.0);
  vec3 length_y = vec3(first_length.y, last.y > first.y + 1 ? 1.0 : 0.0,
                       last.y > first.y ? hi.y - float(last.y) : 0.0);
  vec4 sum = vec4(0.0);
  for (int b = 0; b < 3; ++b) {
    for (int a = 0; a < 3; ++a) {
      float w = length_x[a] * length_y[b];
      if (w == 0.0) continue;
      ivec2 sx = span[a], sy = span[b];
      uvec4 box = corner[4 * sy.y + sx.y] - corner[4 * sy.y + sx.x] - corner[4 * sy.x + sx.y] +
                  corner[4 * sy.x + sx.x];
      sum += w * vec4(box);
    }
  }
  // The area they cover (hi - lo up to rounding; this way a constant map
  // averages to itself exactly).
  ivec2 between = max(last - first - 1, ivec2(0));
  float area_x = length_x.x + float(between.x) * length_x.y + length_x.z;
  float area_y = length_y.x + float(between.y) * length_y.y + length_y.z;
  return sum / (scale * area_x * area_y);
}

// Average over the square of radius r around the point `center` (texel
// units): half-width r + 1/2, so that an integer r is the (2r + 1)^2 box of
// the fixed filter; a fractional r widens it continuously.
vec4 sat_square_average(usampler2DArray sat, int v, vec2 center, float r, float scale) {
  return sat_rectangle_average(sat, v, center, vec2(r + 0.5), scale);
}
