// A spot view's depth, drawn as z0 / z (reversed, far plane at infinity:
// caster_position.glsl), turned into the z-bar every technique reads, once
// per texel rather than once per caster fragment. With d = z0 / z,
// z - z0 = z0 (1 - d) / d; 1 - d is exact for d >= 1/2 (Sterbenz), so the
// near end loses nothing. d = 0 (cleared: nothing drawn) and whatever lay
// beyond z1 read as 1, as they did when the far plane clipped them.
layout(binding = 0) uniform sampler2DArray u_reciprocal_depth;
layout(location = 0) uniform vec2 u_depth_range;  // z0, z1

void main() {
  float d = texelFetch(u_reciprocal_depth, ivec3(gl_FragCoord.xy, 0), 0).r;
  float z0 = u_depth_range.x, z1 = u_depth_range.y;
  gl_FragDepth = d > 0.0 ? clamp(z0 * (1.0 - d) / (d * (z1 - z0)), 0.0, 1.0) : 1.0;
}
