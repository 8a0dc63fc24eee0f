// Half-resolution AO to full resolution, joint bilateral upsampling (Kopf
// et al. 2007): each pixel mixes the AO texels around it with bilinear
// weights times the cross-bilateral weight of the G-buffer texels they were
// computed at, so AO never crosses a depth discontinuity. Where every
// neighbour is rejected (a thin object narrower than an AO texel), the
// neighbour nearest the pixel's tangent plane is taken (nearest-depth
// upsampling).
#include "ssao_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = UNIT_AMBIENT_OCCLUSION) uniform sampler2D ao_in;  // at half resolution
layout(r32f, binding = IMAGE_OUTPUT) uniform writeonly image2D ao_out;  // at the G-buffer's

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, ssao.size.zw))) return;
  vec3 p, n;
  if (!view_surface(texel, p, n)) {
    imageStore(ao_out, texel, vec4(1.0));
    return;
  }
  // AO texel c was computed at G-buffer texel 2c: this texel lies at
  // fraction f (0 or 1/2 along each axis) from `base` towards base + 1.
  ivec2 base = texel / 2;
  vec2 f = vec2(texel - 2 * base) * 0.5;
  float sum = 0.0, weight_sum = 0.0;
  float nearest_value = 1.0, nearest_distance = 1e30;
  for (int j = 0; j < 4; ++j) {
    ivec2 offset = ivec2(j & 1, j >> 1);
    ivec2 c = min(base + offset, ssao.size.xy - 1);
    vec3 pc, nc;
    if (!view_surface(gbuffer_texel(c), pc, nc)) continue;
    float value = texelFetch(ao_in, c, 0).r;
    vec2 bilinear = mix(1.0 - f, f, vec2(offset));
    float w = bilinear.x * bilinear.y * bilateral_weight(p, n, pc, nc);
    sum += w * value;
    weight_sum += w;
    float plane_distance = abs(dot(n, pc - p));
    if (plane_distance < nearest_distance) {
      nearest_distance = plane_distance;
      nearest_value = value;
    }
  }
  imageStore(ao_out, texel, vec4(weight_sum > 1e-3 ? sum / weight_sum : nearest_value));
}
