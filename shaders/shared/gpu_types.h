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

// One light as the shaders see it (one entry of the lights block).
struct GpuLight {
  mat4 view;                     // world -> light view (light looks down -z)
  mat4 view_projection;          // world -> light clip space
  mat4 inverse_view_projection;  // light clip space -> world
  vec4 position_type;            // xyz: position (spot); w: LIGHT_SPOT or LIGHT_DIRECTIONAL
  vec4 direction_cos_outer;      // xyz: unit direction the light shines along; w: cos(outer cone)
  vec4 radiance_cos_inner;       // rgb: colour * intensity; w: cos(inner cone)
  // x: z0, y: z1 (light-space depth range mapped to z-bar = (z - z0)/(z1 - z0));
  // z: world size of one shadow-map texel at unit depth (spot) or anywhere
  //    (directional); w: shadow-map size in texels
  vec4 depth_range;
  // x: width of the light's source: world units at the light (spot), or per
  //    unit of distance, 2 tan(angular radius) (directional); yzw: unused
  vec4 source;
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
};

// Shadow parameters (see ShadowSettings in src/core/settings.hpp for their
// meaning). Scalars only, four to a row, so std140 matches the C++ layout.
struct GpuShadow {
  float constant_bias;  // z-bar units
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
  int unused;
};

// Screen-space ambient occlusion (see SsaoSettings in src/core/settings.hpp).
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

#ifdef __cplusplus
}  // namespace penumbra::gpu
#endif

#endif
