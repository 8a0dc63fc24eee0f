// Percentage-closer filtering (Reeves et al. 1987; GPU Gems ch. 11): the
// mean of biased binary depth tests over a square window around the
// lookup, sampled with a rotated prefix of the Poisson set. Each sample is
// compared with the receiver's plane at that sample (receiver-plane depth,
// from the per-texel depth gradient), so a wide window on a sloped
// receiver does not shadow the receiver itself.
#include "depth_map_hooks.glsl"
#include "occluder_cone.glsl"
#include "penumbra.glsl"
#include "poisson.glsl"
#include "square_samples.glsl"

// PCF's window has a fixed width whatever the light's size, so it counts
// the occluders inside a cone at least this wide (tan of its half-angle):
// an occluder more than 1 / (2 * 0.1) = 5 window widths nearer the light
// than the receiver blurs the whole window, while the lit wall beside a
// receiver at its foot (unless the light grazes it within 5.7 degrees)
// does not darken it.
const float PCF_MIN_CONE_TAN = 0.1;

// z-bar gradient of the receiver's plane per texel of the map, from two
// exact ray-plane intersections one texel away; capped at the slope the
// slope-scaled bias follows, so grazing receivers stay finite.
vec2 receiver_depth_gradient(GpuShadowView view, ShadowLookup s, vec3 normal, float max_slope) {
  vec2 texel_uv = vec2(1.0 / view.depth_range.w);
  float dx = receiver_plane_depth(view, s.position, normal, s.uv + vec2(texel_uv.x, 0.0), s.depth);
  float dy = receiver_plane_depth(view, s.position, normal, s.uv + vec2(0.0, texel_uv.y), s.depth);
  float limit = max_slope * s.texel_depth;
  return clamp(vec2(dx, dy) - s.depth, vec2(-limit), vec2(limit));
}

// Lit fraction over a window `width` texels wide (samples >= 1) of layer
// `layer` (shadow view `view`). `depth` is the biased receiver depth at the
// window's centre; a sample is blocked when its texel is nearer the light
// than the receiver's plane there and inside the cone from the receiver to
// the light (occluder_cone.glsl).
#define SHADOW_PCF_DEFINE(NAME, MAPS, TEXELS, FETCH)                                           \
  float NAME(MAPS depth_maps, int layer, GpuShadowView view, OccluderCone cone, vec2 uv,       \
             float depth, vec2 gradient, float width, int samples, vec2 rotation) {            \
    ivec2 size = TEXELS(depth_maps, layer);                                                           \
    vec2 center = uv * vec2(size);                                                             \
    float lit = 0.0;                                                                           \
    for (int i = 0; i < samples; ++i) {                                                        \
      vec2 offset = rotated_poisson(i, rotation) * (0.5 * width); /* texels */                 \
      ivec2 texel = clamp(ivec2(floor(center + offset)), ivec2(0), size - 1);                  \
      float receiver = depth + dot(gradient, offset);                                          \
      float occluder = FETCH(depth_maps, layer, texel);                                        \
      bool blocked =                                                                           \
          receiver > occluder && texel_occludes(view, texel, size, occluder, cone, false);     \
      lit += blocked ? 0.0 : 1.0;                                                              \
    }                                                                                          \
    return lit / float(samples);                                                               \
  }
SHADOW_PCF_DEFINE(shadow_pcf, sampler2DArray, shadow_map_texels, shadow_map_fetch)

// Lit fraction over the axis-aligned square window `width` texels wide
// around uv, from `samples` points of the pixel's shifted R2 set
// (square_samples.glsl), each the hardware's 2x2 bilinear compare (as
// Filament's PCSS and MJP's optimized PCF take them): a tap averages four
// texels with weights that move continuously, so each sample is a smooth
// function of its position instead of a 0/1 step. One sample is the
// compare at uv itself. The bilinear footprint widens the kernel by a
// one-texel tent (variance 1/6 texel^2 per axis); pcss_kernel_width()
// takes it off.
#define SHADOW_PCF_BILINEAR_DEFINE(NAME, MAPS, TEXELS, COMPARE)                                \
  float NAME(MAPS maps, int layer, vec2 uv, float depth, vec2 gradient, float width,           \
             int samples, vec2 shift) {                                                        \
    vec2 size = vec2(TEXELS(maps, layer));                                                            \
    if (samples <= 1) return COMPARE(maps, layer, uv, depth);                                  \
    float lit = 0.0;                                                                           \
    for (int i = 0; i < samples; ++i) {                                                        \
      vec2 offset = square_sample(i, shift) * (0.5 * width); /* texels */                      \
      lit += COMPARE(maps, layer, uv + offset / size, depth + dot(gradient, offset));          \
    }                                                                                          \
    return lit / float(samples);                                                               \
  }
SHADOW_PCF_BILINEAR_DEFINE(shadow_pcf_bilinear, sampler2DArrayShadow, shadow_map_texels,
                           shadow_map_compare)

// Width of the square of bilinear taps whose result has the spread of a
// `width`-texel box: the box's variance w^2 / 12 per axis, less the tent's
// 1/6, so w_taps = sqrt(w^2 - 2); 0 (the single compare) below that.
float pcss_kernel_width(float width) {
  return sqrt(max(width * width - 2.0, 0.0));
}

// Filter samples for a square `width` texels wide: one per texel of it, a
// density at which the taps' bilinear footprints overlap, so the estimate
// has little noise left; narrow penumbrae take few, wide ones up to
// max_samples.
int pcss_filter_sample_count(float width, int max_samples) {
  return clamp(int(ceil(width * width)), 1, max_samples);
}

// Blocker-search samples for a region `width` texels wide, each gathering
// 2 x 2 texels: one per 4 texels of it, up to max_samples.
int pcss_search_sample_count(float width, int max_samples) {
  return clamp(int(ceil(0.25 * width * width)), 1, max_samples);
}
