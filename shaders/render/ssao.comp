// Screen-space ambient obscurance (seed 003, Task 6). For a pixel at p
// with normal n, the k kernel points p_i = p + t_i w_i lie in the
// hemisphere of radius r around n. Each is projected into the G-buffer,
// where the surface seen is p'; p_i contributes (n . w_i) unless the depth
// buffer hides it:
//   hidden  <=>  |p'.z| + bias < |p_i.z| <= |p'.z| + bias + range r
// (beyond range r the hiding surface is too far in front of p_i to occlude
// p: the seed's range check, which uses range = 5). The sum is divided by
// sum_i (n . w_i), not by k, so that an unoccluded surface gets exactly 1:
// with directions uniform over the hemisphere this estimates the
// cosine-weighted visibility (1/pi) int_H V_r(p, w) (n . w) dw. Where the
// seed reads p' at the centre of the texel under p_i, p' is taken on that
// texel's tangent plane, along p_i's own ray (surface_depth() below).
//
// The kernel is rotated about n per pixel, and its distances shifted, by
// interleaved gradient noise (Jimenez 2014): neighbouring pixels get well
// spread rotations, which the bilateral blur averages out, and every image
// is reproducible.
#include "ssao_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f, binding = IMAGE_OUTPUT) uniform writeonly image2D ao_out;

// Jimenez, "Next Generation Post Processing in Call of Duty: Advanced
// Warfare", SIGGRAPH 2014.
float interleaved_gradient_noise(vec2 p) {
  return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715))));
}

// |p'.z|: the view depth of the surface seen through the texel under
// `point`, taken where the ray through `point` meets that surface's tangent
// plane (the texel's position and normal) rather than at the texel's centre.
// The two differ by up to half a texel of the surface's depth slope, which
// on a plane seen at a grazing angle exceeds the height of the lower
// samples above it: self-occlusion that no fixed bias removes at every
// distance (measured on a plane seen at 3 to 30 degrees: 6.9% of its pixels
// below 0.98 at the default bias, 23% without one). On a plane the
// tangent-plane depth is exact. Within ~1 degree of edge-on the
// extrapolation is unstable and the centre is kept.
float surface_depth(vec3 point, vec3 seen, vec3 seen_normal) {
  float facing = dot(seen_normal, point);  // the camera is at the origin of view space
  if (abs(facing) < 0.02 * length(point)) return -seen.z;
  return -point.z * dot(seen_normal, seen) / facing;
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, ssao.size.xy))) return;
  vec3 p, n;
  if (!view_surface(gbuffer_texel(texel), p, n)) {
    imageStore(ao_out, texel, vec4(1.0));  // background: nothing to occlude
    return;
  }

  // Orthonormal frame around n, rotated by the pixel's angle.
  float angle = 6.28318530718 * interleaved_gradient_noise(vec2(texel));
  float shift = interleaved_gradient_noise(vec2(texel.yx) + 0.5);
  vec3 helper = abs(n.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 t0 = normalize(cross(helper, n));
  vec3 b0 = cross(n, t0);
  vec3 t = cos(angle) * t0 + sin(angle) * b0;
  vec3 b = cross(n, t);

  float visible = 0.0, total = 0.0;
  for (int i = 0; i < ssao.sample_count; ++i) {
    vec4 k = ssao.kernel[i];
    vec3 w = k.x * t + k.y * b + k.z * n;
    // Cranley-Patterson shift of the distance, kept in (0, 1].
    float reach = ssao.radius * (1.0 - fract(k.w + shift));
    vec3 sample_point = p + reach * w;
    float cosine = k.z;  // n . w_i
    total += cosine;

    bool hidden = false;
    vec4 clip = ssao.projection * vec4(sample_point, 1.0);
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    // Points off screen or behind the camera have no depth to test: unoccluded.
    if (clip.w > 0.0 && all(greaterThanEqual(uv, vec2(0.0))) && all(lessThan(uv, vec2(1.0)))) {
      ivec2 seen_texel = min(ivec2(uv * vec2(ssao.size.zw)), ssao.size.zw - 1);
      vec3 seen, seen_normal;
      if (view_surface(seen_texel, seen, seen_normal)) {
        float behind = -sample_point.z - surface_depth(sample_point, seen, seen_normal);
        hidden = behind > ssao.bias && behind <= ssao.bias + ssao.range * ssao.radius;
      }
    }
    if (!hidden) visible += cosine;
  }
  imageStore(ao_out, texel, vec4(visible / total));
}
