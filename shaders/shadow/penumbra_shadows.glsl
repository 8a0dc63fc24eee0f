// penumbra's shadow lookup for an engine's own shaders. Installed, with
// its includes expanded, as share/penumbra/penumbra_shadows.glsl, and
// returned by penumbra::shadow_lookup_glsl(): put it after the engine's
// "#version 450 core" (penumbra::insert_shadow_lookup() does), bind the
// maps with ShadowMaps::bind(), and call
//
//   float penumbra_shadow(int light, vec3 world_position, vec3 world_normal)
//
// in a fragment shader: the fraction of light `light`'s light (1 = lit)
// that reaches the point, for the technique the maps were rendered for
// (chosen at run time from the block: no recompile when it changes). On a
// smooth-shaded surface, pass the triangle's normal and the interpolated
// one it is shaded with:
//
//   float penumbra_shadow(int light, vec3 world_position, vec3 world_normal,
//                         vec3 shading_normal)
//
// (backprojection weighs its source above the shading normal's horizon,
// and pcss and the moments' --soft count only the blockers above it, as
// penumbra's renderer and traced reference do). The
// entry points penumbra_shadow_<technique>() do the same for one
// technique (they must match the maps' technique); the *_at() forms take
// the pixel for the per-pixel sample rotation instead of gl_FragCoord, for
// other shader stages.
//
// The light's view is picked as penumbra's renderer picks it
// (view_select.glsl): a spot light's one view, a point light's cube face,
// a directional light's cascade along the camera, blended into the next
// near each cascade's end, or for the first directional light with
// virtual maps (hard, pcf) the finest clipmap level with a texel per
// pixel, through its page table (virtual_shadow.glsl). The tests per technique are the shared ones
// under shaders/shadow/ (hard.glsl, pcf.glsl, pcss.glsl,
// backprojection.glsl, filtered.glsl with vsm.glsl, esm.glsl, evsm.glsl,
// msm.glsl; filter/sat.glsl), with the biases of lookup.glsl.
#pragma once

#include "../shared/bindings.h"
#include "../shared/gpu_types.h"
#include "lookup.glsl"
#include "view_select.glsl"
#include "hard.glsl"
#include "vsm.glsl"
#include "esm.glsl"
#include "evsm.glsl"
#include "msm.glsl"
#include "filtered.glsl"
#include "../filter/sat.glsl"
#include "soft_moments.glsl"
#include "noise.glsl"
#include "pcf.glsl"
#include "pcss.glsl"
#include "backprojection.glsl"
// A directional light's virtual shadow maps (ShadowMapKind::Virtual),
// read through their page table at the engine's bindings.
#define VIRTUAL_BLOCK_BINDING PENUMBRA_SHADOW_VIRTUAL_BLOCK_BINDING
#define VIRTUAL_PAGE_TABLE_UNIT PENUMBRA_SHADOW_PAGE_TABLE_UNIT
#define VIRTUAL_POOL_UNIT PENUMBRA_SHADOW_PAGE_POOL_UNIT
#define VIRTUAL_NO_TEXEL_DENSITY
#define VIRTUAL_NO_DEPTH_BOUNDS
#include "virtual_shadow.glsl"

// The binding points are the engine's (penumbra::ShadowBindings):
// shadow_lookup_glsl() defines these macros before this text.
layout(std140, binding = PENUMBRA_SHADOW_BLOCK_BINDING) uniform PenumbraShadowBlock {
  GpuShadowBlock penumbra_block;
};
// Every shadow view's map is one layer of these arrays.
layout(binding = PENUMBRA_SHADOW_DEPTH_UNIT) uniform sampler2DArray penumbra_depth;
layout(binding = PENUMBRA_SHADOW_COMPARE_UNIT) uniform sampler2DArrayShadow penumbra_compare;
layout(binding = PENUMBRA_SHADOW_FILTERED_UNIT) uniform sampler2DArray penumbra_filtered;
// With --filter sat: the representation's summed-area tables.
layout(binding = PENUMBRA_SHADOW_SAT_UNIT) uniform usampler2DArray penumbra_sat;

// Fraction of the light that reaches the point according to shadow view v.
// `normal`: the surface's own (its triangle's), for the biases and the
// receiver's plane; `shading_normal`: the one it is shaded with, whose
// horizon weighs the source (backprojection) or bounds its blockers
// (PCSS, occluder_cone_above()). `pixel` seeds backprojection's
// jitter; `noise` in [0, 1) is the pixel's noise value, `rotation` the
// angle 2 pi noise.
float penumbra_view_shadow(int technique, int v, GpuLight light, vec3 world, vec3 normal,
                           vec3 shading_normal, vec2 pixel, float noise, vec2 rotation) {
  GpuShadowView view = penumbra_block.views[v];
  GpuShadow params = penumbra_block.params;
  vec3 to_light = direction_to_light(light, world);
  // The settings the lookup and the bias take.
  GpuShadow lookup_params = technique == TECHNIQUE_BACKPROJECTION
                                ? backprojection_bias_settings(params, normal, to_light)
                                : params;
  ShadowLookup s = shadow_lookup(view, world, normal, lookup_params.normal_offset);
  if (!s.inside) return 1.0;
  bool filterable = technique >= TECHNIQUE_VSM;
  float bias =
      shadow_bias(lookup_params, s, normal, to_light, filterable ? params.blur_radius : 0);
  float z = s.depth - bias;
  if (technique == TECHNIQUE_HARD) return shadow_hard(penumbra_depth, v, s.uv, z, 0.0);
  if (technique == TECHNIQUE_PCF) {
    // PCF, or for one sample the hardware's 2x2 bilinear compare; width 0
    // is the plain test.
    if (params.pcf_width <= 0.0) return shadow_hard(penumbra_depth, v, s.uv, z, 0.0);
    if (params.pcf_samples == 1) return texture(penumbra_compare, vec4(s.uv, float(v), z));
    vec2 gradient = receiver_depth_gradient(view, s, normal, params.max_slope);
    OccluderCone cone = occluder_cone(light, view, s.position, PCF_MIN_CONE_TAN);
    return shadow_pcf(penumbra_depth, v, view, cone, s.uv, z, gradient, params.pcf_width,
                      params.pcf_samples, rotation);
  }
  if (technique == TECHNIQUE_PCSS || technique == TECHNIQUE_BACKPROJECTION) {
    vec2 gradient = receiver_depth_gradient(view, s, normal, params.max_slope);
    if (technique == TECHNIQUE_BACKPROJECTION) {
      return shadow_backprojection(penumbra_depth, penumbra_filtered, v, view, s, z, gradient,
                                   normal, shading_normal,
                                   int(light.position_type.w) == LIGHT_POINT,
                                   ivec2(floor(pixel)), params.backprojection_cells);
    }
    // PCSS: the cone the light's source really subtends (its width is the
    // settings' light_size, or sun_angle for the sun).
    return shadow_pcss(penumbra_depth, penumbra_compare, v, view, s, z,
                       blocker_plane_gradient(gradient, normal, to_light),
                       occluder_cone_above(light, view, s.position, world, shading_normal),
                       rotation, noise, params.pcss_blocker_samples, params.pcss_filter_samples);
  }
  if (!filterable) return 1.0;
  bool quantized = penumbra_block.counts.w != 0;
  bool sat = params.filter_type == FILTER_SAT;
  float lit;
  if (sat && params.soft_moments != 0) {
    lit = shadow_soft_moments(penumbra_sat, penumbra_depth, technique, quantized, params, v, view,
                              s, z, light, world, normal, shading_normal, rotation);
  } else {
    // The SAT's (2W + 1)^2 box centred on the lookup point, or the filtered map.
    vec4 m = sat ? sat_square_average(penumbra_sat, v,
                                      s.uv * vec2(textureSize(penumbra_sat, 0).xy),
                                      float(params.blur_radius), params.sat_scale)
                 : texture(penumbra_filtered, vec3(s.uv, float(v)));
    lit = filtered_lit_fraction_of(technique, quantized, params, m, z, s.texel_depth);
  }
  return technique == TECHNIQUE_ESM ? lit : reduce_light_bleeding(lit, params.bleed_reduction);
}

// Fraction of light `light_index`'s light that reaches the point, for
// `technique` (TECHNIQUE_*); `pixel` seeds the per-pixel sample rotation.
float penumbra_shadow_technique_at(int technique, int light_index, vec3 world, vec3 normal,
                                   vec3 shading_normal, vec2 pixel) {
  if (technique == TECHNIQUE_NONE || light_index < 0 || light_index >= penumbra_block.counts.x) {
    return 1.0;
  }
  GpuLight light = penumbra_block.lights[light_index];
  float noise = interleaved_gradient_noise(floor(pixel));
  float angle = 6.28318530718 * noise;
  vec2 rotation = vec2(cos(angle), sin(angle));
  // The light with virtual maps (hard and pcf) reads them, not cascades.
  if (light_index < MAX_LIGHTS && virtual_shadow.lights[light_index].y > 0 &&
      (technique == TECHNIQUE_HARD || technique == TECHNIQUE_PCF)) {
    return virtual_shadow_factor_of(technique, light_index, penumbra_block.params, light, world,
                                    normal, rotation);
  }
  float camera_depth = -(penumbra_block.camera_view * vec4(world, 1.0)).z;
  ViewSelection selected = select_shadow_view(light, world, camera_depth);
  // One call site in a loop over the one or two views: the technique's
  // code is inlined once, not twice.
  float lit[2] = float[](1.0, 1.0);
  int count = selected.blend > 0.0 ? 2 : 1;
  for (int k = 0; k < count; ++k) {
    lit[k] = penumbra_view_shadow(technique, k == 0 ? selected.view : selected.next, light, world,
                                  normal, shading_normal, pixel, noise, rotation);
  }
  return count == 2 ? mix(lit[0], lit[1], selected.blend) : lit[0];
}

float penumbra_shadow_at(int light, vec3 world_position, vec3 world_normal, vec2 pixel) {
  return penumbra_shadow_technique_at(penumbra_block.counts.z, light, world_position, world_normal,
                                      world_normal, pixel);
}
// A smooth-shaded surface: its triangle's normal `world_normal` and the
// interpolated normal it is shaded with, `shading_normal`, whose horizon
// weighs backprojection's source as the traced reference does
// (docs/comparing.md, "The terminator model") and bounds the blockers
// pcss and the moments' --soft count (occluder_cone_above()); hard, pcf
// and the moments' fixed filter read world_normal alone.
float penumbra_shadow_at(int light, vec3 world_position, vec3 world_normal, vec3 shading_normal,
                         vec2 pixel) {
  return penumbra_shadow_technique_at(penumbra_block.counts.z, light, world_position, world_normal,
                                      shading_normal, pixel);
}

#ifndef PENUMBRA_NO_FRAGMENT_ENTRY_POINTS
float penumbra_shadow(int light, vec3 world_position, vec3 world_normal) {
  return penumbra_shadow_at(light, world_position, world_normal, gl_FragCoord.xy);
}
float penumbra_shadow(int light, vec3 world_position, vec3 world_normal, vec3 shading_normal) {
  return penumbra_shadow_at(light, world_position, world_normal, shading_normal, gl_FragCoord.xy);
}
float penumbra_shadow_hard(int light, vec3 world_position, vec3 world_normal) {
  return penumbra_shadow_technique_at(TECHNIQUE_HARD, light, world_position, world_normal,
                                      world_normal, gl_FragCoord.xy);
}
float penumbra_shadow_pcf(int light, vec3 world_position, vec3 world_normal) {
  return penumbra_shadow_technique_at(TECHNIQUE_PCF, light, world_position, world_normal,
                                      world_normal, gl_FragCoord.xy);
}
float penumbra_shadow_pcss(int light, vec3 world_position, vec3 world_normal) {
  return penumbra_shadow_technique_at(TECHNIQUE_PCSS, light, world_position, world_normal,
                                      world_normal, gl_FragCoord.xy);
}
float penumbra_shadow_pcss(int light, vec3 world_position, vec3 world_normal,
                           vec3 shading_normal) {
  return penumbra_shadow_technique_at(TECHNIQUE_PCSS, light, world_position, world_normal,
                                      shading_normal, gl_FragCoord.xy);
}
float penumbra_shadow_backprojection(int light, vec3 world_position, vec3 world_normal) {
  return penumbra_shadow_technique_at(TECHNIQUE_BACKPROJECTION, light, world_position,
                                      world_normal, world_normal, gl_FragCoord.xy);
}
float penumbra_shadow_backprojection(int light, vec3 world_position, vec3 world_normal,
                                     vec3 shading_normal) {
  return penumbra_shadow_technique_at(TECHNIQUE_BACKPROJECTION, light, world_position,
                                      world_normal, shading_normal, gl_FragCoord.xy);
}
float penumbra_shadow_vsm(int light, vec3 world_position, vec3 world_normal) {
  return penumbra_shadow_technique_at(TECHNIQUE_VSM, light, world_position, world_normal,
                                      world_normal, gl_FragCoord.xy);
}
float penumbra_shadow_esm(int light, vec3 world_position, vec3 world_normal) {
  return penumbra_shadow_technique_at(TECHNIQUE_ESM, light, world_position, world_normal,
                                      world_normal, gl_FragCoord.xy);
}
float penumbra_shadow_evsm2(int light, vec3 world_position, vec3 world_normal) {
  return penumbra_shadow_technique_at(TECHNIQUE_EVSM2, light, world_position, world_normal,
                                      world_normal, gl_FragCoord.xy);
}
float penumbra_shadow_evsm4(int light, vec3 world_position, vec3 world_normal) {
  return penumbra_shadow_technique_at(TECHNIQUE_EVSM4, light, world_position, world_normal,
                                      world_normal, gl_FragCoord.xy);
}
float penumbra_shadow_msm(int light, vec3 world_position, vec3 world_normal) {
  return penumbra_shadow_technique_at(TECHNIQUE_MSM, light, world_position, world_normal,
                                      world_normal, gl_FragCoord.xy);
}
float penumbra_shadow_msm16(int light, vec3 world_position, vec3 world_normal) {
  return penumbra_shadow_technique_at(TECHNIQUE_MSM16, light, world_position, world_normal,
                                      world_normal, gl_FragCoord.xy);
}
#endif
