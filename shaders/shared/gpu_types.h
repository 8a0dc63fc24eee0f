// Uniform-block structs shared by the C++ host and the GLSL shaders. Only
// vec4/mat4/ivec4 members, so std140 and the C++ layout agree (checked by
// static_asserts on the host side and a test against the driver's offsets).
#ifndef PENUMBRA_GPU_TYPES_H
#define PENUMBRA_GPU_TYPES_H

#include "bindings.h"

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace penumbra::gpu {
using vec4 = glm::vec4;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
#endif

// One shadow view: a 2D map that is one layer of the shadow-map arrays. A
// spot light has one, a point light six (the faces of a cube), a
// directional light one per cascade (see include/penumbra/shadow/shadow_views.hpp).
struct GpuShadowView {
  mat4 view;                     // world -> view space (the view looks down -z)
  mat4 view_projection;          // world -> clip space
  mat4 inverse_view_projection;  // clip space -> world
  // x: z0, y: z1 (the view's depth range mapped to z-bar = (z - z0)/(z1 - z0),
  //    where z is the distance along -z, or from the eye for radial depth);
  // z: world size of one texel at unit depth (perspective) or anywhere
  //    (orthographic); w: map size in texels
  vec4 depth_range;
  // Width of the light's source: world units at the light (spot, point), or
  // per unit of distance, 2 tan(angular radius) (directional).
  float source_width;
  int perspective;   // 1: perspective projection, 0: orthographic
  int radial_depth;  // 1: z is the distance from the eye (point lights), 0: depth along -z
  // The layer of the depth maps holding this view's second surfaces (the
  // nearest facing the eye behind the first ones: ShadowMapPass::
  // second_layer(), for backprojection); 0: none.
  int second_layer;
};

// One light as the shaders see it (one entry of the lights block).
struct GpuLight {
  vec4 position_type;        // xyz: position (spot, point); w: LIGHT_SPOT, _DIRECTIONAL or _POINT
  vec4 direction_cos_outer;  // xyz: unit direction the light shines along; w: cos(outer cone)
  vec4 radiance_cos_inner;   // rgb: colour * intensity; w: cos(inner cone)
  // x: index of the light's first view in the shadow-views block; y: its
  // view count (1 spot, 6 point, the cascade count directional); zw: unused
  ivec4 views;
  // Directional lights: the camera view depth where cascade i ends (the
  // last one covers everything the camera sees).
  vec4 cascade_end;
  // x: fraction of each cascade, at its far end, over which it blends into
  //    the next one; y: the camera's near plane (where the first starts);
  //    zw: unused
  vec4 cascade_blend;
};

// Per-frame camera data.
struct GpuFrame {
  mat4 view;
  mat4 projection;
  mat4 inverse_view_projection;
  vec4 camera_position;  // xyz: world position
  vec4 viewport;         // xy: size in pixels, zw: 1 / size
  // x: light count, y: VIEW_*, z: light shown by the shadow view,
  // w: 1 when the ambient-occlusion texture is bound, 0: ambient unoccluded
  ivec4 options;
  vec4 ambient;  // rgb: ambient light colour
  // Screen-space contact shadows (ShadowSettings::contact_shadows,
  // shaders/render/contact_shadow.glsl; on where the lighting program is
  // compiled with CONTACT_SHADOWS 1): the march's length and the depth
  // thickness of what it meets, in world units; its step count.
  float contact_length;
  float contact_thickness;
  int contact_steps;
  int unused0;
};

// Shadow parameters (see ShadowSettings in include/penumbra/settings.hpp for their
// meaning). Scalars only, four to a row, so std140 matches the C++ layout.
struct GpuShadow {
  float constant_bias;  // texels
  float slope_bias;     // texels of the receiver's depth slope
  float normal_offset;  // texels
  float max_slope;      // largest tan(theta) the slope bias follows
  float esm_c;
  float msm_alpha;  // the alpha for the technique in use (32-bit, or 16-bit/SAT)
  float bleed_reduction;
  float vsm_min_variance;
  int blur_radius;          // texels
  float sat_scale;          // fixed-point scale of the summed-area table (values * scale)
  float filter_slope_bias;  // extra slope-scaled bias per texel of filter radius
  float pcf_width;          // texels
  int pcf_samples;
  int pcss_blocker_samples;
  int pcss_filter_samples;
  int two_moment_blockers;  // 1: msm --soft estimates blockers as vsm does
  // --accumulate (src/render/accumulation.hpp; its rays are compiled in
  // with ACCUMULATE_SUBFRAMES): the sub-frame's point of a spot light's
  // square, in [0, 1]^2; the sub-frame index, which seeds each pixel's
  // dither.
  float accumulate_u;
  float accumulate_v;
  int backprojection_cells;  // the settings' backprojection_cells (shadow_backprojection())
  int accumulate_frame;
  float evsm_positive;  // EVSM exponents c+ and c- (shaders/shadow/evsm.glsl)
  float evsm_negative;
  int filter_type;   // FILTER_* of the representation (FILTER_SAT: summed-area tables)
  int soft_moments;  // 1: --soft, penumbra-sized filters from the summed-area tables
  // The source's outward normal at the sub-frame's point (spot: the light's
  // direction; point: the sphere's normal); 1 when the shadow view writes
  // (lit, lit * weight, weight) for the Accumulator to weigh.
  float accumulate_normal_x;
  float accumulate_normal_y;
  float accumulate_normal_z;
  int accumulate_weighted;
  // --accumulate: the sub-frame's cell of a spot light's square, which
  // holds its point (corner and size in [0, 1]^2), and the cell's column of
  // accumulate_columns and row of the accumulate_rows its column holds
  // (ShadowSettings::subframe_cell).
  float accumulate_cell_x;
  float accumulate_cell_y;
  float accumulate_cell_width;
  float accumulate_cell_height;
  int accumulate_column;
  int accumulate_columns;
  int accumulate_row;
  int accumulate_rows;
};

// Screen-space ambient occlusion (see SsaoSettings in include/penumbra/settings.hpp).
struct GpuSsao {
  mat4 view;                // world -> camera view
  mat4 projection;          // camera view -> clip
  mat4 inverse_projection;  // clip -> camera view
  // xyz: unit direction in the normal's frame (z along the normal);
  // w: distance along it as a fraction of the radius, in (0, 1)
  vec4 kernel[SSAO_MAX_SAMPLES];
  ivec4 size;        // xy: AO texture size, zw: G-buffer size
  float radius;      // world units
  float bias;        // world units of view depth
  float range;       // multiples of the radius
  int sample_count;  // k <= SSAO_MAX_SAMPLES
  int blur_radius;   // AO texels
  int scale;         // G-buffer texels per AO texel along each axis (1 or 2)
  float unused0;
  float unused1;
};

// The lights' virtual shadow maps (src/shadow/virtual_clipmap.hpp): one
// view per level, light after light: a directional light's orthographic
// clipmap levels over their 128 x 128 pages, a spot light's perspective
// mip levels (level m: 16,384 / 2^m texels, depth_range.w, its pages from
// (0, 0)). A level's page-table layer is its index here.
struct GpuVirtualShadow {
  GpuShadowView levels[MAX_VIRTUAL_VIEWS];
  // xy: the world page of level l's first page; z: 1 when the level's
  // pages are stale as a whole (its texel or depth range changed); w: 1
  // when its origin moved (pages that scrolled out are freed).
  ivec4 origins[MAX_VIRTUAL_VIEWS];
  // The origins of the last frame, for the pages that scrolled out.
  ivec4 previous_origins[MAX_VIRTUAL_VIEWS];
  // Per scene light: x: its first level, y: its level count (0: the light
  // reads no virtual maps); zw: unused
  ivec4 lights[MAX_LIGHTS];
  vec4 camera;     // xyz: where footprints are measured from; w: footprint per unit distance
  vec4 view_axis;  // xyz: the camera's unit view direction; w: unused
  // x: level 0's texel of the directional light (world units); y: texels
  // a lookup reads around its own (normal offset, filter, bilinear taps,
  // margin); z: the level bias, in half levels finer (0 from the host; the
  // allocation writes the one it chose, 0 .. VIRTUAL_LEVEL_BIASES - 1,
  // before the pages are drawn); w: the window, in texels, of the source's
  // search region the lookup also reads (pcss: VIRTUAL_PCSS_WINDOW,
  // backprojection: VIRTUAL_BACKPROJECTION_WINDOW; 0: none)
  vec4 params;
  // x: unused; y: level count (all lights); z: pool pages; w: caster
  // draw commands (one per batch)
  ivec4 counts;
};

// The shadow core's one block for an engine's shaders (include/penumbra/
// shadow_block.hpp documents it; shaders/shadow/penumbra_shadows.glsl
// reads it): the parameters, the camera that picks cascades, every light's
// shadow data and every shadow view. 5984 bytes, under the 16 KiB every
// OpenGL 4.5 device allows a uniform block.
struct GpuShadowBlock {
  GpuShadow params;
  mat4 camera_view;  // world -> the engine camera's view space (cascades: depth along -z)
  // x: light count, y: shadow-view count, z: the technique the maps hold
  // (TECHNIQUE_*), w: 1 when MSM moments are stored quantized (msm16)
  ivec4 counts;
  // Light i's shadow data (radiance_cos_inner is the light's too, for an
  // engine that lights with it; the lookup does not read it).
  GpuLight lights[MAX_LIGHTS];
  GpuShadowView views[MAX_SHADOW_VIEWS];
};

#ifdef __cplusplus
}  // namespace penumbra::gpu
#endif

#endif
