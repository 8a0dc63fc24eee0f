// Which fraction of a point's rise to the smooth surface
// (shaders/scene/smooth_surface.glsl) its shadow lookup towards direction
// l gets, with unit shading normal n and triangle normal ng on n's side:
// all of it at grazing light, none once both cosines reach the cutoff
// (Cycles' shadow_ray_offset; src/reference/terminator_offset.hpp:
// terminator_offset_amount, whose cutoff this repeats).
const float TERMINATOR_OFFSET_CUTOFF = 0.1;

float terminator_offset_amount(vec3 n, vec3 ng, vec3 l) {
  float nl = max(dot(n, l), 0.0), ngl = dot(ng, l);
  float amount = nl < TERMINATOR_OFFSET_CUTOFF ? 2.0 - (ngl + nl) / TERMINATOR_OFFSET_CUTOFF
                                               : 1.0 - ngl / TERMINATOR_OFFSET_CUTOFF;
  return clamp(amount, 0.0, 1.0);
}
