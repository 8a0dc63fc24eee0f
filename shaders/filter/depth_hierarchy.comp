// One level of a depth map's min/max hierarchy (DepthHierarchyPass): each
// texel of level L + 1 holds the nearest and farthest z-bar of the 2x2
// texels of level L it covers, level 0 those of the depth map's 2x2 texels
// (Guennebaud, Barthe and Paulin, Eurographics 2007; Schwarz and
// Stamminger, Eurographics 2007), and their mean, the depth of the cell's
// micro-patch. Backprojection reads it for the region that can hold a
// receiver's blockers and for the patches of a wide region
// (shaders/shadow/backprojection.glsl).
// Levels are floor(size / 2) wide, as OpenGL's chain, so the last texel of
// a level takes the finer level's odd row or column as well: a cell's
// bounds cover every texel under it. FROM_DEPTH: the finer level is the
// depth map array itself. Workgroup z is the layer.
#include "../shared/bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;

#if FROM_DEPTH
layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray finer;
ivec2 finer_size() { return textureSize(finer, 0).xy; }
vec3 finer_cell(ivec3 q) { return vec3(texelFetch(finer, q, 0).r); }
#else
layout(rgba32f, binding = IMAGE_OUTPUT) uniform readonly image2DArray finer;
ivec2 finer_size() { return imageSize(finer).xy; }
vec3 finer_cell(ivec3 q) { return imageLoad(finer, q).rgb; }
#endif
layout(rgba32f, binding = IMAGE_OUTPUT_2) uniform writeonly image2DArray coarser;

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  ivec2 coarse = imageSize(coarser).xy;
  if (any(greaterThanEqual(p.xy, coarse))) return;
  ivec2 fine = finer_size();
  ivec2 q0 = min(2 * p.xy, fine - 1);
  ivec2 q1 = min(mix(q0 + 1, fine - 1, equal(p.xy, coarse - 1)), fine - 1);
  vec2 bounds = vec2(1.0e30, -1.0e30);
  float sum = 0.0;
  for (int y = q0.y; y <= q1.y; ++y) {
    for (int x = q0.x; x <= q1.x; ++x) {
      vec3 m = finer_cell(ivec3(x, y, p.z));
      bounds = vec2(min(bounds.x, m.x), max(bounds.y, m.y));
      sum += m.z;
    }
  }
  // The finer cells' means weigh alike: a last row or column that takes an
  // odd remainder weighs its texels a little less than the others.
  vec2 count = vec2(q1 - q0 + 1);
  imageStore(coarser, p, vec4(bounds, sum / (count.x * count.y), 0.0));
}
