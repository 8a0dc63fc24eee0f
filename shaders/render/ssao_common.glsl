// What the SSAO passes share: their parameter block, the G-buffer read back
// as camera-view positions and normals, and the weight that keeps the blur
// and the upsampling on one surface.
#include "../shared/bindings.h"
#include "../shared/gpu_types.h"
#include "camera_depth.glsl"

layout(std140, binding = BINDING_SSAO_UBO) uniform SsaoBlock { GpuSsao ssao; };

layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D gbuffer_depth;
layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D gbuffer_normal;

// A neighbour farther from the centre's tangent plane than this fraction of
// the centre's view depth is another surface.
#define SSAO_PLANE_TOLERANCE 0.02
// Exponent of the normals' cosine in the bilateral weight: 0.61 at 10
// degrees apart, 1.5e-5 at 45 (curved surfaces blur, creases do not).
#define SSAO_NORMAL_POWER 32.0

// The G-buffer texel an AO texel stands for: itself at full resolution, the
// top-left texel of its 2x2 block at half resolution.
ivec2 gbuffer_texel(ivec2 ao_texel) { return min(ao_texel * ssao.scale, ssao.size.zw - 1); }

// Camera-view position of the surface seen through a G-buffer texel's centre.
vec3 view_position(ivec2 texel) {
  vec2 ndc = (vec2(texel) + 0.5) / vec2(ssao.size.zw) * 2.0 - 1.0;
  return position_from_depth(ssao.inverse_projection, ndc, texelFetch(gbuffer_depth, texel, 0).r);
}

// The surface seen through a G-buffer texel, in camera view; false where
// no geometry was drawn (the G-buffer's normal.w is 0 there).
bool view_surface(ivec2 texel, out vec3 position, out vec3 normal) {
  vec4 normal_shininess = texelFetch(gbuffer_normal, texel, 0);
  position = vec3(0.0);
  normal = vec3(0.0, 0.0, 1.0);
  if (normal_shininess.w == 0.0) return false;
  position = view_position(texel);
  // The view matrix is a rotation and a translation: normals transform
  // with its upper 3x3.
  normal = normalize(mat3(ssao.view) * normal_shininess.xyz);
  return true;
}

// Cross-bilateral weight (Tomasi & Manduchi 1998, with the range kernel on
// the G-buffer's geometry as in joint bilateral upsampling, Kopf et al.
// 2007): 1 for a neighbour on the centre's tangent plane with its normal,
// falling to 0 off that plane (depth discontinuities) or across a crease.
// Measuring the distance to the plane rather than the depth difference keeps
// surfaces seen at grazing angles, whose depth changes fast from texel to
// texel, blurred along their length.
float bilateral_weight(vec3 center, vec3 center_normal, vec3 neighbour, vec3 neighbour_normal) {
  float plane_distance = abs(dot(center_normal, neighbour - center));
  float depth_weight = max(0.0, 1.0 - plane_distance / (SSAO_PLANE_TOLERANCE * abs(center.z)));
  float normal_weight = pow(max(dot(center_normal, neighbour_normal), 0.0), SSAO_NORMAL_POWER);
  return depth_weight * normal_weight;
}
