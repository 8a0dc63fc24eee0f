// One level of a filtered map's mip chain (MipChainPass): each texel of
// level L + 1 is the mean of the 2x2 texels of level L it covers. Every
// representation the chain is made for is a linear one (moments, warped
// moments, exp(c (z - 1)), msm16's affine quantization of the moments), so
// the mean of its texels is the representation of the union of their
// depths, as a wider filter would make it; a trilinear lookup between
// levels stays a normalized filter. Odd sizes: level L + 1 is floor(size /
// 2) wide (OpenGL's chain), so the last row or column of level L is left
// out (and a 2 x 1 level's texel is the mean of its two). IMAGE_FORMAT: the map's image format; workgroup z is the layer.
#include "../shared/bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;

// Level L (read) and level L + 1 (written) of the same texture array.
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform readonly image2DArray finer;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT_2) uniform writeonly image2DArray coarser;

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p.xy, imageSize(coarser).xy))) return;
  // A level one texel wide or high reads its one column or row twice.
  ivec2 last = imageSize(finer).xy - 1;
  ivec2 q0 = 2 * p.xy, q1 = min(q0 + 1, last);
  vec4 sum = imageLoad(finer, ivec3(q0, p.z)) + imageLoad(finer, ivec3(q1.x, q0.y, p.z)) +
             imageLoad(finer, ivec3(q0.x, q1.y, p.z)) + imageLoad(finer, ivec3(q1, p.z));
  imageStore(coarser, p, 0.25 * sum);
}
