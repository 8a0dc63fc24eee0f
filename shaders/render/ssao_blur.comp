// One direction of the SSAO blur: a Gaussian of 2 R + 1 taps (s = R / 2,
// as the shadow-map blur) whose weights are multiplied by the cross-
// bilateral weight, so the noise of the per-pixel kernel rotation is
// averaged away along each surface but nothing is mixed across depth
// discontinuities or creases. (Separable, like most SSAO blurs: the
// bilateral weight makes it only approximately a 2D filter.)
//
// Defines: AXIS (0: along x, 1: along y).
#include "ssao_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = UNIT_AMBIENT_OCCLUSION) uniform sampler2D ao_in;
layout(r32f, binding = IMAGE_OUTPUT) uniform writeonly image2D ao_out;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, ssao.size.xy))) return;
  vec3 p, n;
  if (!view_surface(gbuffer_texel(texel), p, n)) {
    imageStore(ao_out, texel, vec4(1.0));
    return;
  }
#if AXIS == 0
  const ivec2 axis_step = ivec2(1, 0);
#else
  const ivec2 axis_step = ivec2(0, 1);
#endif
  int radius = ssao.blur_radius;
  float s = max(0.5 * float(radius), 0.5);
  float sum = 0.0, weight_sum = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    ivec2 q = texel + i * axis_step;
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ssao.size.xy))) continue;
    vec3 pq, nq;
    if (!view_surface(gbuffer_texel(q), pq, nq)) continue;
    float w = exp(-float(i * i) / (2.0 * s * s)) * bilateral_weight(p, n, pq, nq);
    sum += w * texelFetch(ao_in, q, 0).r;
    weight_sum += w;
  }
  // The centre tap has weight 1, so weight_sum >= 1.
  imageStore(ao_out, texel, vec4(sum / weight_sum));
}
