// Summed-area tables (Crow 1984; Hensley et al. 2005) in 32-bit fixed
// point. Values in [0, 1] are stored as round(v * scale) and summed with
// wrap-around unsigned arithmetic: the four-corner difference of a box is
// exact as long as the box's true sum fits in 32 bits, however large the
// table's own prefix sums grow, so precision does not degrade with the
// map's size (a float table of a 4096^2 map would lose its low bits).

// Average of the box of texels [center - radius, center + radius]^2 of
// layer `layer`, cropped to the map (nothing from outside is mixed in; the
// average is over the texels inside).
vec4 sat_box_average(usampler2DArray sat, int layer, ivec2 center, int radius, float scale) {
  ivec2 size = textureSize(sat, 0).xy;
  ivec2 lo = clamp(center - radius, ivec2(0), size - 1);
  ivec2 hi = clamp(center + radius, ivec2(0), size - 1);
  uvec4 sum = texelFetch(sat, ivec3(hi, layer), 0);
  if (lo.x > 0) sum -= texelFetch(sat, ivec3(lo.x - 1, hi.y, layer), 0);
  if (lo.y > 0) sum -= texelFetch(sat, ivec3(hi.x, lo.y - 1, layer), 0);
  if (lo.x > 0 && lo.y > 0) sum += texelFetch(sat, ivec3(lo - 1, layer), 0);
  float area = float((hi.x - lo.x + 1) * (hi.y - lo.y + 1));
  return vec4(sum) / (scale * area);
}
