


// Deferred lighting: ambient * AO + sum over lights of
// shadow * (Lambert diffuse + normalized Blinn-Phong specular).
// Compile-time defines: SHADOW_TECHNIQUE (TECHNIQUE_*), SHADOW_FILTER
// (FILTER_*), MSM_QUANTIZED (0/1: moments in the quantization basis),
// SOFT_SHADOWS (0/1: penumbra-sized filters from the summed-area table),
// SHADOW_MIPS (0/1: the filtered map has a mip chain, read over the
// pixel's footprint), VIRTUAL_SHADOWS (0/1: the lights with levels in
// virtual_shadow.lights read virtual shadow maps, shaders/shadow/virtual_shadow.glsl),
// LIGHTING_VIEWS (LIGHTING_VIEWS_*: the views the program writes),
// CONTACT_SHADOWS (0/1: the screen-space march, contact_shadow.glsl) and
// ACCUMULATE_SUBFRAMES (0/1: a hard --accumulate sub-frame's rays).
#ifndef LIGHTING_VIEWS
#define LIGHTING_VIEWS LIGHTING_VIEWS_SHADED
#endif
#ifndef CONTACT_SHADOWS
#define CONTACT_SHADOWS 0
#endif
#ifndef ACCUMULATE_SUBFRAMES
#define ACCUMULATE_SUBFRAMES 0
#endif
#include "../common/uniforms.glsl"
#include "../common/world_position.glsl"
#include "../shadow/lookup.glsl"
#include "../shadow/view_select.glsl"
#include "../shadow/texel_density.glsl"
#include "../shadow/hard.glsl"
#include "../shadow/vsm.glsl"
#include "../shadow/esm.glsl"
#include "../shadow/evsm.glsl"
#include "../shadow/msm.glsl"
#include "../shadow/filtered.glsl"
#include "../filter/sat.glsl"
#include "../shadow/noise.glsl"
#include "../shadow/penumbra.glsl"
#include "../shadow/pcf.glsl"
#include "../shadow/pcss.glsl"
#include "../shadow/soft_moments.glsl"
#include "../shadow/accumulate.glsl"
#include "../shadow/backprojection.glsl"
#if VIRTUAL_SHADOWS
#include "../shadow/virtual_shadow.glsl"
#endif
#include "terminator_offset.glsl"
#include "camera_depth.glsl"

layout(std140, binding = BINDING_SHADOW_UBO) uniform ShadowBlock { GpuShadow shadow_params; };

layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D gbuffer_depth;
layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D gbuffer_normal;
layout(binding = UNIT_GBUFFER_ALBEDO) uniform sampler2D gbuffer_albedo;
layout(binding = UNIT_GBUFFER_SPECULAR) uniform sampler2D gbuffer_specular;
// xyz: the triangle's normal, w: the rise to the smooth surface along the
// normal (shaders/scene/smooth_surface.glsl), of which each light's
// lookups take the part its direction calls for (lifted_point).
layout(binding = UNIT_GBUFFER_FACET) uniform sampler2D gbuffer_facet;
// Read only when frame.options.w is 1 (SSAO on).
layout(binding = UNIT_AMBIENT_OCCLUSION) uniform sampler2D ambient_occlusion;
// Every shadow view's map is one layer of these arrays (the layer is the
// view's index in the shadow-views block).
layout(binding = UNIT_SHADOW_DEPTH) uniform sampler2DArray shadow_depth;
// The same depth maps through a comparison sampler: the hardware's 2x2
// bilinear percentage-closer test.
layout(binding = UNIT_SHADOW_COMPARE) uniform sampler2DArrayShadow shadow_compare;
#if SHADOW_FILTER == FILTER_SAT && SHADOW_TECHNIQUE != TECHNIQUE_BACKPROJECTION
layout(binding = UNIT_SHADOW_FILTERED) uniform usampler2DArray shadow_sat;
#else
// The technique's representation, filtered or not; sampled bilinearly, or
// trilinearly and anisotropically with SHADOW_MIPS. Backprojection's min/max
// depth hierarchy (DepthHierarchyPass), read with texelFetch.
layout(binding = UNIT_SHADOW_FILTERED) uniform sampler2DArray shadow_filtered;
#endif

in vec2 v_uv;
#if defined(SHADOW_COUNT_FETCHES) && SHADOW_COUNT_FETCHES
// Texel reads per pixel (LightingPass::count_fetches, fetch_count.glsl).
layout(r32ui, binding = IMAGE_OUTPUT) uniform uimage2D shadow_fetch_counts;
#endif
layout(location = 0) out vec4 out_color;  // alpha: 1 where geometry was seen

// A lookup's lit fraction `lit`, its texel reads added to the pixel's
// count in the counting variant (fetch_count.glsl).
#if defined(SHADOW_COUNT_FETCHES) && SHADOW_COUNT_FETCHES
float counted_lookup(float lit) {
  imageAtomicAdd(shadow_fetch_counts, ivec2(gl_FragCoord.xy), shadow_fetches);
  shadow_fetches = 0u;
  return lit;
}
#else
#define counted_lookup(lit) (lit)
#endif
#if LIGHTING_VIEWS == LIGHTING_VIEWS_SHADED
// The chosen light's shadow view (VIEW_SHADOW) in either view: the lit
// image's pass leaves it too, so a study that reads both pays one pass.
layout(location = 1) out vec4 out_shadow;
#endif

#include "contact_shadow.glsl"

// What one pixel covers of the receiver: the world offsets from the
// pixel's point to where the camera rays through the next pixel in x and
// in y meet the receiver's tangent plane. A mipmapped lookup projects them
// into the shadow map as its uv derivatives. In a deferred pass the
// screen-space derivatives of the reconstructed position (dFdx) would mix
// the 2x2 quad's surfaces at every silhouette and pick the coarsest mip
// there (a halo), and the lookups sit in non-uniform control flow (per
// light, per view) where implicit derivatives are undefined; the plane's
// are exact for the pixel's own surface and defined everywhere.
struct PixelFootprint {
  vec3 dx, dy;
};

// The offset towards the ray through pixel-centre NDC `ndc`, on the plane.
// Where that ray runs (nearly) along the plane or meets it behind the
// camera, and to bound grazing footprints, at most 256 times the offset
// to the ray at the point's own camera distance (beyond that the lookup
// is at the map's coarsest levels anyway).
vec3 footprint_offset(vec2 ndc, vec3 world, vec3 n) {
  vec3 origin = position_from_depth(frame.inverse_view_projection, ndc, CAMERA_NEAR_DEPTH);
  vec3 far_point = position_from_depth(frame.inverse_view_projection, ndc, CAMERA_FAR_DEPTH);
  vec3 direction = far_point - origin;
  // The ray's point at the camera depth of `world` (depth is affine along it).
  float d0 = -(frame.view * vec4(origin, 1.0)).z;
  float d1 = -(frame.view * vec4(origin + direction, 1.0)).z;
  float dw = -(frame.view * vec4(world, 1.0)).z;
  vec3 level = origin + direction * ((dw - d0) / (d1 - d0)) - world;
  float limit = 256.0 * length(level);
  float denominator = dot(n, direction);
  float t = dot(n, world - origin) / denominator;
  vec3 offset = origin + t * direction - world;
  float len = length(offset);
  bool hit = abs(denominator) > 1e-12 && t > 0.0 && !isinf(len) && !isnan(len);
  if (hit && len <= limit) return offset;
  vec3 along = hit && len > 0.0 ? offset / len : level / max(length(level), 1e-30);
  return along * limit;
}

PixelFootprint pixel_footprint(ivec2 pixel, vec3 world, vec3 n) {
  vec2 ndc = (vec2(pixel) + 0.5) * frame.viewport.zw * 2.0 - 1.0;
  vec2 step = 2.0 * frame.viewport.zw;
  return PixelFootprint(footprint_offset(ndc + vec2(step.x, 0.0), world, n),
                        footprint_offset(ndc + vec2(0.0, step.y), world, n));
}

#if SHADOW_TECHNIQUE >= TECHNIQUE_VSM
// View v's filtered representation at the lookup point; with SHADOW_MIPS
// averaged over the pixel's footprint, whose sides in uv are duv_dx and
// duv_dy.
vec4 filtered_map(int v, vec2 uv, vec2 duv_dx, vec2 duv_dy) {
#if SHADOW_FILTER == FILTER_SAT
  // The (2W + 1)^2 box, centred on the lookup point itself rather than on
  // the texel it falls in: half-width W + 1/2 texels.
  return sat_square_average(shadow_sat, v, uv * vec2(textureSize(shadow_sat, 0).xy),
                            float(shadow_params.blur_radius), shadow_params.sat_scale);
#elif SHADOW_MIPS
  return textureGrad(shadow_filtered, vec3(uv, float(v)), duv_dx, duv_dy);
#else
  return texture(shadow_filtered, vec3(uv, float(v)));
#endif
}

// The technique's tests of filtered map values (shaders/shadow/filtered.glsl).
float filtered_lit_fraction(vec4 m, float z, float texel_depth) {
  return filtered_lit_fraction_of(SHADOW_TECHNIQUE, MSM_QUANTIZED != 0, shadow_params, m, z,
                                  texel_depth);
}
float filtered_mean_depth(vec4 m) {
  return filtered_mean_depth_of(SHADOW_TECHNIQUE, MSM_QUANTIZED != 0, shadow_params, m);
}
#endif

#if SHADOW_TECHNIQUE >= TECHNIQUE_VSM && SHADOW_FILTER == FILTER_SAT && SOFT_SHADOWS
// Moment soft shadows (shaders/shadow/soft_moments.glsl) of view v.
float soft_moment_shadow(int v, ShadowLookup s, float z, GpuLight light, vec3 world, vec3 normal,
                         vec3 shading_normal, vec2 rotation) {
  return shadow_soft_moments(shadow_sat, shadow_depth, SHADOW_TECHNIQUE, MSM_QUANTIZED != 0,
                             shadow_params, v, shadow_views[v], s, z, light, world, normal,
                             shading_normal, rotation);
}
#endif

// The filtered hard-shadow reference (--view shadow-reference): the binary
// depth tests of the unfiltered map, averaged with the kernel the
// technique's filter applies, by brute force; each texel is tested against
// the receiver's plane where that texel's ray meets it. It is what a
// filtered technique approximates. Test quality: up to (2W+2)^2 fetches
// per pixel for the SAT's box at its sub-texel position, 4 (2W+1)^2 for the
// Gaussian, which is read bilinearly like the blurred map.
layout(std430, binding = BINDING_FILTER_WEIGHTS_SSBO) readonly buffer ReferenceWeights {
  float reference_weights[];  // 2 W + 1: the filter's 1D kernel
};

struct ReceiverPlane {
  vec3 world;   // the lookup point
  vec3 normal;
  float depth;  // its z-bar
  float bias;
};

// The biased test of one texel of view v against the receiver's plane there.
float depth_test(int v, ivec2 texel, ReceiverPlane plane) {
  vec2 uv = (vec2(texel) + 0.5) / vec2(textureSize(shadow_depth, 0).xy);
  float z =
      receiver_plane_depth(shadow_views[v], plane.world, plane.normal, uv, plane.depth) - plane.bias;
  return z <= texelFetch(shadow_depth, ivec3(texel, v), 0).r ? 1.0 : 0.0;
}

float filtered_hard_reference(int v, vec2 uv, ReceiverPlane z) {
  const int r = shadow_params.blur_radius;
  ivec2 size = textureSize(shadow_depth, 0).xy;
#if SHADOW_FILTER == FILTER_SAT
  // The rectangle of filtered_map(): half-width W + 1/2 around the lookup
  // point, cropped to the map; each texel's test weighted by the area of
  // the texel the rectangle covers (as sat_rectangle_average() weights it).
  vec2 center = clamp(uv * vec2(size), vec2(0.0), vec2(size));
  vec2 lo = clamp(center - (float(r) + 0.5), vec2(0.0), vec2(size));
  vec2 hi = clamp(center + (float(r) + 0.5), vec2(0.0), vec2(size));
  ivec2 first = ivec2(floor(lo)), last = max(ivec2(ceil(hi)) - 1, first);
  float sum = 0.0;
  for (int y = first.y; y <= last.y; ++y) {
    float wy = min(float(y + 1), hi.y) - max(float(y), lo.y);
    for (int x = first.x; x <= last.x; ++x) {
      float wx = min(float(x + 1), hi.x) - max(float(x), lo.x);
      sum += wx * wy * depth_test(v, ivec2(x, y), z);
    }
  }
  return sum / ((hi.x - lo.x) * (hi.y - lo.y));
#else
  // The blurred map (edges clamped), read bilinearly at uv.
  vec2 p = uv * vec2(size) - 0.5;
  ivec2 base = ivec2(floor(p));
  vec2 f = p - vec2(base);
  float corners[4];
  for (int c = 0; c < 4; ++c) {
    ivec2 center = base + ivec2(c & 1, c >> 1);
    float sum = 0.0;
    for (int y = -r; y <= r; ++y)
      for (int x = -r; x <= r; ++x)
        sum += reference_weights[x + r] * reference_weights[y + r] *
               depth_test(v, clamp(center + ivec2(x, y), ivec2(0), size - 1), z);
    corners[c] = sum;
  }
  return mix(mix(corners[0], corners[1], f.x), mix(corners[2], corners[3], f.x), f.y);
#endif
}

#if SHADOW_TECHNIQUE == TECHNIQUE_PCF || SHADOW_TECHNIQUE == TECHNIQUE_PCSS
// PCF, or for one sample the hardware's 2x2 bilinear compare; width 0 is
// the plain test.
float pcf_lit_fraction(int v, ShadowLookup s, float z, vec2 gradient, OccluderCone cone,
                       float width, int samples, vec2 rotation) {
  if (width <= 0.0) return shadow_hard(shadow_depth, v, s.uv, z, 0.0);
  if (samples == 1) return texture(shadow_compare, vec4(s.uv, float(v), z));
  return shadow_pcf(shadow_depth, v, shadow_views[v], cone, s.uv, z, gradient, width, samples,
                    rotation);
}
#endif

#if SHADOW_TECHNIQUE == TECHNIQUE_PCSS
// PCSS (shaders/shadow/pcss.glsl) with the settings' sample counts; its
// noise is the value `rotation` was made from (main()).
float pcss_lit_fraction(int v, ShadowLookup s, float z, vec2 gradient, OccluderCone cone,
                        vec2 rotation) {
  return shadow_pcss(shadow_depth, shadow_compare, v, shadow_views[v], s, z, gradient, cone,
                     rotation, interleaved_gradient_noise(floor(gl_FragCoord.xy)),
                     shadow_params.pcss_blocker_samples, shadow_params.pcss_filter_samples);
}
#endif

// Fraction of light i's light that reaches the point (1 = lit) according
// to shadow view v. `rotation` is the pixel's (cos, sin) rotation of the
// sample set. `normal` (the triangle's) places the receiver's plane;
// `shading_normal` is the horizon an area light's source is weighed
// against (the terminator model, docs/comparing.md).
float view_shadow_factor(int v, GpuLight light, vec3 world, vec3 normal, vec3 shading_normal,
                         bool reference, vec2 rotation, PixelFootprint footprint) {
  GpuShadowView view = shadow_views[v];
  vec3 to_light = direction_to_light(light, world);
  // The settings the lookup and the bias take.
#if SHADOW_TECHNIQUE == TECHNIQUE_BACKPROJECTION
  GpuShadow lookup_params = backprojection_bias_settings(shadow_params, normal, to_light);
#else
  GpuShadow lookup_params = shadow_params;
#endif
  ShadowLookup s = shadow_lookup(view, world, normal, lookup_params.normal_offset);
  if (!s.inside) return 1.0;
  float filter_radius =
      SHADOW_TECHNIQUE >= TECHNIQUE_VSM && !reference ? float(shadow_params.blur_radius) : 0.0;
#if SHADOW_MIPS
  // The pixel's footprint in the map. A lookup over it averages the
  // receiver's own sloped plane over its long side as well: half of it
  // (beyond one texel) adds to the filter's radius in the slope bias.
  vec2 duv_dx = shadow_map_uv(view, s.position + footprint.dx) - s.uv;
  vec2 duv_dy = shadow_map_uv(view, s.position + footprint.dy) - s.uv;
  vec2 map_size = vec2(textureSize(shadow_filtered, 0).xy);
  float footprint_texels = max(length(duv_dx * map_size), length(duv_dy * map_size));
  if (!reference) filter_radius += 0.5 * max(footprint_texels - 1.0, 0.0);
#else
  vec2 duv_dx = vec2(0.0), duv_dy = vec2(0.0);
#endif
  float bias = shadow_bias(lookup_params, s, normal, to_light, filter_radius);
  if (reference) {
    return filtered_hard_reference(v, s.uv, ReceiverPlane(s.position, normal, s.depth, bias));
  }
  float z = s.depth - bias;
#if SHADOW_TECHNIQUE == TECHNIQUE_HARD
#if ACCUMULATE_SUBFRAMES
  if (view.perspective != 0 && view.radial_depth == 0) {
    // An --accumulate sub-frame of a spot light: rays to the pixel's own
    // points of the sub-frame's cell.
    vec2 gradient = receiver_depth_gradient(view, s, normal, shadow_params.max_slope);
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    AccumulateCell cell = accumulate_cell(
        pixel, vec2(shadow_params.accumulate_u, shadow_params.accumulate_v),
        vec4(shadow_params.accumulate_cell_x, shadow_params.accumulate_cell_y,
             shadow_params.accumulate_cell_width, shadow_params.accumulate_cell_height),
        ivec4(shadow_params.accumulate_column, shadow_params.accumulate_columns,
              shadow_params.accumulate_row, shadow_params.accumulate_rows));
    float lit = 0.0;
    for (int q = 0; q < ACCUMULATE_RAYS; ++q) {
      vec3 random = accumulate_hash(pixel, shadow_params.accumulate_frame * ACCUMULATE_RAYS + q);
      vec2 offset = accumulate_light_offset(view, cell, q, random.xy);
      lit += shadow_hard_dithered(shadow_depth, v, view, s, z, gradient, offset);
    }
    return lit / float(ACCUMULATE_RAYS);
  }
#endif
  return shadow_hard(shadow_depth, v, s.uv, z, 0.0);
#elif SHADOW_TECHNIQUE == TECHNIQUE_PCF || SHADOW_TECHNIQUE == TECHNIQUE_PCSS
  vec2 gradient = receiver_depth_gradient(view, s, normal, shadow_params.max_slope);
#if SHADOW_TECHNIQUE == TECHNIQUE_PCF
  OccluderCone cone = occluder_cone(light, view, s.position, PCF_MIN_CONE_TAN);
  return pcf_lit_fraction(v, s, z, gradient, cone, shadow_params.pcf_width,
                          shadow_params.pcf_samples, rotation);
#else
  // PCSS models the light's source itself: the cone it really subtends.
  return counted_lookup(
      pcss_lit_fraction(v, s, z, blocker_plane_gradient(gradient, normal, to_light),
                        occluder_cone_above(light, view, s.position, world, shading_normal),
                        rotation));
#endif
#elif SHADOW_TECHNIQUE == TECHNIQUE_BACKPROJECTION
  vec2 gradient = receiver_depth_gradient(view, s, normal, shadow_params.max_slope);
  return counted_lookup(shadow_backprojection(
      shadow_depth, shadow_filtered, v, view, s, z, gradient, normal, shading_normal,
      int(light.position_type.w) == LIGHT_POINT, ivec2(gl_FragCoord.xy),
      shadow_params.backprojection_cells));
#elif SHADOW_TECHNIQUE >= TECHNIQUE_VSM
#if SHADOW_FILTER == FILTER_SAT && SOFT_SHADOWS
  float lit = soft_moment_shadow(v, s, z, light, world, normal, shading_normal, rotation);
#else
  float lit = filtered_lit_fraction(filtered_map(v, s.uv, duv_dx, duv_dy), z, s.texel_depth);
#endif
#if SHADOW_TECHNIQUE == TECHNIQUE_ESM
  return lit;
#else
  return reduce_light_bleeding(lit, shadow_params.bleed_reduction);
#endif
#else
  return 1.0;
#endif
}

// The point's depth along the camera's view direction (selects cascades).
float camera_depth(vec3 world) {
  return -(frame.view * vec4(world, 1.0)).z;
}

// Fraction of light i's light that reaches the point (1 = lit): from the
// shadow view the point falls in, blended with the next cascade near the
// end of a directional light's cascade.
float shadow_factor(int i, vec3 world, vec3 normal, vec3 shading_normal, bool reference,
                    vec2 rotation, PixelFootprint footprint) {
#if SHADOW_TECHNIQUE == TECHNIQUE_NONE
  return 1.0;
#else
  GpuLight light = lights[i];
#if VIRTUAL_SHADOWS
  if (virtual_shadow.lights[i].y > 0) {
    float noise = interleaved_gradient_noise(floor(gl_FragCoord.xy));
    return counted_lookup(virtual_shadow_factor(i, shadow_params, light, world, normal,
                                                shading_normal, rotation, noise));
  }
#endif
  ViewSelection selected = select_shadow_view(light, world, camera_depth(world));
  // One call site in a loop over the one or two views: the technique's
  // code is inlined once, not twice (half the shader).
  float lit[2] = float[](1.0, 1.0);
  int count = selected.blend > 0.0 ? 2 : 1;
  for (int k = 0; k < count; ++k) {
    lit[k] = view_shadow_factor(k == 0 ? selected.view : selected.next, light, world, normal,
                                shading_normal, reference, rotation, footprint);
  }
  return count == 2 ? mix(lit[0], lit[1], selected.blend) : lit[0];
#endif
}

// Light i's shadow factor `lit` at `start` (the point its lookups use),
// with the contact shadows when they are on: the smaller of the two. Both
// estimate the visibility of the same source, and each misses occluders
// the other sees (the march: those off screen, hidden or beyond its
// length; the map: those under its bias); where both see one, a product
// would count it twice and darken a penumbra below either estimate. n is
// the shading normal, whose horizon weighs the source (see
// contact_visible_source()).
float with_contact_shadow(float lit, int i, ivec2 pixel, vec3 start, vec3 n) {
  if (lit <= 0.0) return lit;
  GpuLight light = lights[i];
  // The source's angular radius as source_above_horizon() takes it, but a
  // spot light's square as its equal-area disc (w / sqrt(pi)).
  float width = shadow_views[light.views.x].source_width;
  if (int(light.position_type.w) == LIGHT_DIRECTIONAL) {
    vec3 to_sun = -light.direction_cos_outer.xyz;
    return min(lit, contact_lit_fraction(pixel, start, n, to_sun, 1e30, 0.5 * width));
  }
  vec3 d = light.position_type.xyz - start;
  float reach = length(d);
  if (!(reach > 0.0)) return lit;
  float radius = int(light.position_type.w) == LIGHT_POINT ? 0.5 * width : 0.56418958 * width;
  return min(lit, contact_lit_fraction(pixel, start, n, d / reach, reach, radius / reach));
}

// Distinct colours for the shadow views of one light (the cascades view).
vec3 view_colour(int k) {
  const vec3 palette[MAX_CASCADES + 2] =
      vec3[](vec3(0.9, 0.25, 0.2), vec3(0.25, 0.8, 0.25), vec3(0.2, 0.4, 0.95),
             vec3(0.95, 0.85, 0.2), vec3(0.8, 0.3, 0.85), vec3(0.2, 0.85, 0.85));
  return palette[clamp(k, 0, MAX_CASCADES + 1)];
}

// Light arriving from light i (irradiance on a surface facing it), and the
// unit direction towards it.
vec3 incident_light(int i, vec3 world, out vec3 to_light) {
  GpuLight light = lights[i];
  vec3 radiance = light.radiance_cos_inner.rgb;
  if (int(light.position_type.w) == LIGHT_DIRECTIONAL) {
    to_light = -light.direction_cos_outer.xyz;
    return radiance;
  }
  vec3 d = light.position_type.xyz - world;
  float distance2 = max(dot(d, d), 1e-8);
  to_light = d * inversesqrt(distance2);
  // Inverse-square fall-off of a point source's intensity.
  if (int(light.position_type.w) == LIGHT_POINT) return radiance / distance2;
  float cos_axis = dot(-to_light, light.direction_cos_outer.xyz);
  float cone = smoothstep(light.direction_cos_outer.w, light.radiance_cos_inner.w, cos_axis);
  return radiance * cone / distance2;
}

// Whether some point of light i's source lies above the horizon of the
// surface at `world` with normal n: within the source's radius of the
// tangent plane at its centre (a spot light's square: half its diagonal;
// a point light's sphere: its radius; the sun's disc: its angular radius).
// With a point source it is the plain n . l > 0.
bool source_above_horizon(GpuLight light, vec3 world, vec3 n) {
  float width = shadow_views[light.views.x].source_width;
  if (int(light.position_type.w) == LIGHT_DIRECTIONAL) {
    // source_width is 2 tan(angular radius) for the sun.
    return dot(n, -light.direction_cos_outer.xyz) > -sin(atan(0.5 * width));
  }
  float radius = int(light.position_type.w) == LIGHT_POINT ? 0.5 * width : 0.70710678 * width;
  return dot(n, light.position_type.xyz - world) > -radius;
}

// Where the shadow lookups of `light` start for the point `world` with
// shading normal n: raised along n by the part of its rise to the smooth
// surface (facet.w) that the direction to the source's centre calls for,
// against its triangle's plane, as the traced reference starts its rays
// (src/reference/terminator_offset.hpp).
vec3 lifted_point(GpuLight light, vec3 world, vec3 n, vec4 facet) {
  vec3 l = int(light.position_type.w) == LIGHT_DIRECTIONAL
               ? -light.direction_cos_outer.xyz
               : normalize(light.position_type.xyz - world);
  return world + terminator_offset_amount(n, normalize(facet.xyz), l) * facet.w * n;
}

// What this sub-frame's point of light i's source sends a receiver at
// `world` with normal n, up to a constant (--accumulate, shadow view): the
// weight of its shadow in the ratio of irradiances the traced reference
// computes (src/reference/traced_reference.hpp). cos theta_source
// cos theta_receiver / d^2 for a spot light's square or a point light's
// sphere, cos theta_receiver for a direction of the sun's disc; 0 behind
// the source, or below the tangent plane of the shading normal n, as the
// reference excludes such points.
float accumulate_source_weight(GpuLight light, vec3 world, vec3 n) {
  if (int(light.position_type.w) == LIGHT_DIRECTIONAL) {
    return max(dot(n, -light.direction_cos_outer.xyz), 0.0);
  }
  vec3 d = light.position_type.xyz - world;
  float distance2 = dot(d, d);
  if (!(distance2 > 0.0)) return 0.0;
  vec3 w = d * inversesqrt(distance2);
  vec3 source_normal = vec3(shadow_params.accumulate_normal_x, shadow_params.accumulate_normal_y,
                            shadow_params.accumulate_normal_z);
  float cos_receiver = dot(n, w);
  float cos_source = -dot(source_normal, w);
  if (cos_receiver <= 0.0 || cos_source <= 0.0) return 0.0;
  return cos_source * cos_receiver / distance2;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 normal_shininess = texelFetch(gbuffer_normal, pixel, 0);
  int view = frame.options.y;
  if (normal_shininess.w == 0.0) {  // background
    bool unoccluded = view == VIEW_SHADOW || view == VIEW_SHADOW_REFERENCE || view == VIEW_AO;
    out_color = view == VIEW_FINAL ? vec4(frame.ambient.rgb * 0.5, 0.0)
                                   : vec4(unoccluded ? vec3(1.0) : vec3(0.0), 0.0);
#if LIGHTING_VIEWS == LIGHTING_VIEWS_SHADED
    out_shadow = vec4(1.0, 1.0, 1.0, 0.0);
#endif
    return;
  }
  vec3 n = normalize(normal_shininess.xyz);
  vec3 world = world_position(pixel, texelFetch(gbuffer_depth, pixel, 0).r);
  vec4 facet = texelFetch(gbuffer_facet, pixel, 0);
  vec3 facet_normal = normalize(facet.xyz);
  vec3 albedo = texelFetch(gbuffer_albedo, pixel, 0).rgb;
  // Fraction of the ambient light that reaches the point.
  float ao = frame.options.w != 0 ? texelFetch(ambient_occlusion, pixel, 0).r : 1.0;
#if LIGHTING_VIEWS == LIGHTING_VIEWS_INSPECT
  if (view == VIEW_NORMALS) {
    out_color = vec4(n * 0.5 + 0.5, 1.0);
    return;
  }
  if (view == VIEW_ALBEDO) {
    out_color = vec4(albedo, 1.0);
    return;
  }
  if (view == VIEW_AO) {
    out_color = vec4(vec3(ao), 1.0);
    return;
  }
  if (view == VIEW_CASCADES) {
    // The shadow view (cascade or cube face) the shadow of the chosen light
    // reads here, as a colour. In the blend band towards the next cascade
    // both are read: diagonal stripes of both colours, the next one's
    // stripes as wide as its weight.
    GpuLight light = lights[frame.options.z];
    ViewSelection selected = select_shadow_view(light, world, camera_depth(world));
    bool striped = fract(float(pixel.x + pixel.y) / 8.0) < selected.blend;
    int shown = striped ? selected.next : selected.view;
    // Black where a view the point reads does not cover it: no shadow map
    // has data there.
    bool inside = shadow_lookup(shadow_views[selected.view], world, n, 0.0).inside &&
                  (selected.blend == 0.0 ||
                   shadow_lookup(shadow_views[selected.next], world, n, 0.0).inside);
    out_color = vec4(inside ? view_colour(shown - light.views.x) : vec3(0.0), 1.0);
    return;
  }
  if (view == VIEW_PAGES) {
    // The virtual page the chosen light's lookup reads here: a colour per
    // level (clipmap or mip), bright where the page was rendered this frame, dark
    // where it was cached; page borders as thin dark lines; black where no
    // page holds the point (or the light has no virtual maps).
    vec3 colour = vec3(0.0);
#if VIRTUAL_SHADOWS
    if (virtual_shadow.lights[frame.options.z].y > 0) {
      int level = virtual_resident_level(frame.options.z, world, facet_normal);
      if (level >= 0) {
        vec2 uv = shadow_map_uv(virtual_shadow.levels[level], world) *
                  float(virtual_level_texels(level) / VIRTUAL_PAGE_TEXELS);
        uint entry = virtual_page_entry(level, ivec2(floor(uv)));
        // Hues around the wheel, one per level.
        float shown = float(level - virtual_shadow.lights[frame.options.z].x);
        vec3 hue = clamp(abs(fract(shown * 0.2 + vec3(0.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0,
                         0.0, 1.0);
        colour = (entry & PAGE_RENDERED) != 0u ? mix(hue, vec3(1.0), 0.15) : 0.4 * hue;
        vec2 border = min(fract(uv), 1.0 - fract(uv)) * float(VIRTUAL_PAGE_TEXELS);
        if (min(border.x, border.y) < 1.0) colour *= 0.25;
      }
    }
#endif
    out_color = vec4(colour, 1.0);
    return;
  }
  if (view == VIEW_TEXEL_DENSITY || view == VIEW_TEXEL_DENSITY_VALUES) {
    // The chosen light's texels per pixel on the pixel's own triangle
    // (shaders/shadow/texel_density.glsl).
    GpuLight light = lights[frame.options.z];
    PixelFootprint on_facet = pixel_footprint(pixel, world, facet_normal);
    ShadingTexel texel = shading_texel(light, world, camera_depth(world));
#if VIRTUAL_SHADOWS
    if (virtual_shadow.lights[frame.options.z].y > 0) {
      texel = virtual_shading_texel(frame.options.z, world, facet_normal);
    }
#endif
    float density = texels_per_pixel(texel, on_facet.dx, on_facet.dy, facet_normal,
                                     direction_to_light(light, world));
    out_color = vec4(view == VIEW_TEXEL_DENSITY ? texel_density_colour(density) : vec3(density),
                     1.0);
    return;
  }
  out_color = vec4(0.0);  // not a view of this program
#else
  float angle = 6.28318530718 * interleaved_gradient_noise(vec2(pixel));
#if SHADOW_MIPS
  PixelFootprint footprint = pixel_footprint(pixel, world, n);
#else
  PixelFootprint footprint = PixelFootprint(vec3(0.0), vec3(0.0));
#endif
  vec2 rotation = vec2(cos(angle), sin(angle));

  // The shadow views read the chosen light alone; the lit image sums every
  // light and keeps the chosen one's shadow view as well. One loop, so
  // that the technique's lookup (shadow_factor) and the contact shadows
  // have one call site: the shader compiler inlines each call, and two
  // call sites would double the shader.
  const bool reference = LIGHTING_VIEWS == LIGHTING_VIEWS_REFERENCE;
  bool shadow_view = reference || view == VIEW_SHADOW;
  int first_light = shadow_view ? frame.options.z : 0;
  int light_end = shadow_view ? first_light + 1 : frame.options.x;
  vec3 specular = texelFetch(gbuffer_specular, pixel, 0).rgb;
  float shininess = normal_shininess.w;
  vec3 to_eye = normalize(frame.camera_position.xyz - world);
  vec3 color = frame.ambient.rgb * albedo * ao;
  // The chosen light's shadow view. Where no point of its source is above
  // the horizon of the shading normal no light arrives, occluders or not:
  // 0, and alpha 0 (not judged, as the traced reference marks it).
  // Elsewhere the technique decides, also on surfaces turned away from the
  // light's centre, which an area light's source still reaches over their
  // horizon, and below their triangle's plane (from the point the
  // terminator model lifts).
  vec4 shadow = vec4(0.0);
  for (int i = first_light; i < light_end; ++i) {
    vec3 to_light = vec3(0.0);
    vec3 irradiance = incident_light(i, world, to_light);
    bool lights_pixel =
        !shadow_view && dot(n, to_light) > 0.0 && any(notEqual(irradiance, vec3(0.0)));
    bool judged = i == frame.options.z && source_above_horizon(lights[i], world, n);
    if (!lights_pixel && !judged) continue;
    vec3 start = lifted_point(lights[i], world, n, facet);
    float lit = shadow_factor(i, start, facet_normal, n, reference, rotation, footprint);
#if CONTACT_SHADOWS
    if (!reference) lit = with_contact_shadow(lit, i, pixel, start, n);
#endif
    if (judged) {
      float weight = accumulate_source_weight(lights[i], world, n);
      shadow = shadow_params.accumulate_weighted != 0 ? vec4(lit, vec2(lit, 1.0) * weight, 1.0)
                                                      : vec4(vec3(lit), 1.0);
    }
    if (!lights_pixel) continue;
    vec3 h = normalize(to_light + to_eye);
    // Normalized Blinn-Phong: (s + 8) / 8 keeps the highlight's energy
    // constant as the exponent changes (Akenine-Moller et al., RTR 4th ed.).
    vec3 brdf = albedo + specular * ((shininess + 8.0) / 8.0) * pow(max(dot(n, h), 0.0), shininess);
    color += lit * irradiance * dot(n, to_light) * brdf;
  }
#if LIGHTING_VIEWS == LIGHTING_VIEWS_SHADED
  out_shadow = shadow;
#endif
  if (shadow_view) {
    out_color = shadow;
    return;
  }
  out_color = vec4(color, 1.0);
#endif
}
