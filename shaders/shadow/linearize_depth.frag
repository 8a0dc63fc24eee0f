// A spot view's depth, drawn as z0 / z (reversed, far plane at infinity:
// caster_position.glsl), turned into the z-bar every technique reads, once
// per texel rather than once per caster fragment. With d = z0 / z,
// z - z0 = z0 (1 - d) / d; 1 - d is exact for d >= 1/2 (Sterbenz), so the
// near end loses nothing. d = 0 (cleared: nothing drawn) and whatever lay
// beyond z1 read as 1, as they did when the far plane clipped them.
//
// MULTISAMPLE 1 (--shadow-msaa above 1): the scratch layer and the target
// are multisampled; reading gl_SampleID runs this once per sample, so
// every sample of the target gets its own sample's z-bar.
#ifndef MULTISAMPLE
#define MULTISAMPLE 0
#endif

#if MULTISAMPLE
layout(binding = 0) uniform sampler2DMSArray u_reciprocal_depth;
#else
layout(binding = 0) uniform sampler2DArray u_reciprocal_depth;
#endif
layout(location = 0) uniform vec2 u_depth_range;  // z0, z1

void main() {
#if MULTISAMPLE
  float d = texelFetch(u_reciprocal_depth, ivec3(gl_FragCoord.xy, 0), gl_SampleID).r;
#else
  float d = texelFetch(u_reciprocal_depth, ivec3(gl_FragCoord.xy, 0), 0).r;
#endif
  float z0 = u_depth_range.x, z1 = u_depth_range.y;
  gl_FragDepth = d > 0.0 ? clamp(z0 * (1.0 - d) / (d * (z1 - z0)), 0.0, 1.0) : 1.0;
}
