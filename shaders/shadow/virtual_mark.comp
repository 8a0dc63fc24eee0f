// Virtual shadow maps, marking: for each pixel the camera sees (its depth
// buffer; CameraDepthBuffer) and each light with virtual maps, the pages
// its lookup reads under each level bias (virtual_level_biased(), bias k:
// PAGE_WANTED(k)) in the page table; the allocation then keeps the finest
// bias whose pages fit the pool. The lookup reads around its texel: the
// normal offset, the filter's window, the bilinear taps
// (virtual_shadow.params.y texels in all), so the marked square is
// widened by as much; PCSS's and backprojection's windows also at the
// coarser levels they read them from.
#include "../shared/bindings.h"
#include "../shared/gpu_types.h"
#include "lookup.glsl"
#include "virtual_lookup.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(location = 0) uniform mat4 u_inverse_view_projection;  // NDC -> world
layout(location = 1) uniform ivec2 u_size;                    // the depth buffer's pixels
layout(location = 2) uniform int u_zero_to_one;  // clip control GL_ZERO_TO_ONE: NDC z = depth
layout(location = 3) uniform float u_background;  // the depth of pixels that see nothing
layout(location = 4) uniform int u_has_normal;    // 1: the normals at UNIT_GBUFFER_FACET

layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D camera_depth;
// The triangle's normal (CameraDepthBuffer::normal_texture): the one the
// lookup picks its level with.
layout(binding = UNIT_GBUFFER_FACET) uniform sampler2D camera_normal;
layout(r32ui, binding = IMAGE_OUTPUT) uniform uimage2DArray page_table;

// The world position of the pixel's centre at window depth `depth`.
vec3 camera_world(ivec2 pixel, float depth) {
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(u_size) * 2.0 - 1.0;
  float ndc_z = u_zero_to_one != 0 ? depth : 2.0 * depth - 1.0;
  vec4 p = u_inverse_view_projection * vec4(ndc, ndc_z, 1.0);
  return p.xyz / p.w;
}

// Without the engine's normals: the surface's, from the neighbouring
// pixels' positions (on each axis the side nearer in depth, so a
// silhouette's far side does not tilt it); its sign does not matter
// (virtual_level_coordinate() takes the cosines' magnitudes).
vec3 depth_normal(ivec2 pixel, vec3 world) {
  vec3 d[2];
  for (int axis = 0; axis < 2; ++axis) {
    ivec2 step = axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
    ivec2 a = clamp(pixel + step, ivec2(0), u_size - 1);
    ivec2 b = clamp(pixel - step, ivec2(0), u_size - 1);
    vec3 pa = camera_world(a, texelFetch(camera_depth, a, 0).r) - world;
    vec3 pb = world - camera_world(b, texelFetch(camera_depth, b, 0).r);
    d[axis] = dot(pa, pa) <= dot(pb, pb) ? pa : pb;
  }
  vec3 n = cross(d[0], d[1]);
  if (dot(n, n) == 0.0) return vec3(0.0, 0.0, 1.0);
  return normalize(n);
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, u_size))) return;
  float depth = texelFetch(camera_depth, pixel, 0).r;
  if (depth == u_background) return;
  vec3 world = camera_world(pixel, depth);
  vec3 normal = u_has_normal != 0 ? normalize(texelFetch(camera_normal, pixel, 0).xyz)
                                  : depth_normal(pixel, world);
  // PCSS and backprojection (params.w: their window, in texels) read the
  // source's search region at the levels from the receiver's up to the one
  // where it fits the window (virtual_search_level()).
  float window = virtual_shadow.params.w;
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    if (virtual_shadow.lights[i].y == 0) continue;
    for (int bias = 0; bias < VIRTUAL_LEVEL_BIASES; ++bias) {
      int level = virtual_level_biased(i, world, normal, bias);
      int last_level = window > 0.0 ? virtual_search_level(i, level, world, window) : level;
      uint wanted = PAGE_WANTED(bias);
      for (int l = level; l <= last_level; ++l) {
        GpuShadowView view = virtual_shadow.levels[l];
        vec4 clip = view.view_projection * vec4(world, 1.0);
        // A spot map holds nothing for points outside its frustum (they are
        // lit: shadow_lookup()'s `inside`).
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        if (view.perspective != 0 &&
            (clip.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))))) {
          break;
        }
        int texels = virtual_level_texels(l);
        vec2 texel = uv * float(texels);
        float reach = virtual_shadow.params.y;
        if (window > 0.0) reach += 0.5 * min(virtual_search_texels(level, l, world), window);
        ivec2 last_page = ivec2(texels / VIRTUAL_PAGE_TEXELS - 1);
        ivec2 first =
            clamp(ivec2(floor((texel - reach) / float(VIRTUAL_PAGE_TEXELS))), ivec2(0), last_page);
        ivec2 last =
            clamp(ivec2(floor((texel + reach) / float(VIRTUAL_PAGE_TEXELS))), ivec2(0), last_page);
        for (int y = first.y; y <= last.y; ++y) {
          for (int x = first.x; x <= last.x; ++x) {
            ivec3 entry = ivec3(virtual_level_slot(l, ivec2(x, y)), l);
            // Most neighbours ask for the same page: an atomic only for the first.
            if ((imageLoad(page_table, entry).r & wanted) == 0u) {
              imageAtomicOr(page_table, entry, wanted);
            }
          }
        }
      }
    }
  }
}
