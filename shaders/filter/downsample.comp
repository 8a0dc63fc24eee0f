// One level of a filtered map's mip chain (MipChainPass): each texel of
// level L + 1 is the mean of the 2x2 texels of level L it covers. Every
// representation the chain is made for is a linear one (moments, warped
// moments, exp(c (z - 1)), msm16's affine quantization of the moments), so
// the mean of its texels is the representation of the union of their
// depths, as a wider filter would make it; a trilinear lookup between
// levels stays a normalized filter. Odd sizes: level L + 1 is floor(size /
// 2) wide (OpenGL's chain), so the last row or column of level L is left
// out. IMAGE_FORMAT: the map's image format; workgroup z is the layer.
#include "../shared/bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;

// Level L (read) and level L + 1 (written) of the same texture array.
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform readonly image2DArray finer;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT_2) uniform writeonly image2DArray coarser;

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p.xy, imageSize(coarser).xy))) return;
  ivec3 q = ivec3(2 * p.xy, p.z);
  vec4 sum = imageLoad(finer, q) + imageLoad(finer, q + ivec3(1, 0, 0)) +
             imageLoad(finer, q + ivec3(0, 1, 0)) + imageLoad(finer, q + ivec3(1, 1, 0));
  imageStore(coarser, p, 0.25 * sum);
}
