// Resolve: the light's depth map (z-bar) -> the technique's filterable
// representation. REPRESENTATION is the TECHNIQUE_* of vsm, esm, msm or
// msm16; MSM_QUANTIZED (0/1) whether the moments are stored in the
// quantization basis (see uses_quantized_moments()); IMAGE_FORMAT the
// matching image format. Every layer of the depth-map array (one per
// shadow view) at once: workgroup z is the layer.
#include "../shared/bindings.h"
#include "../shadow/esm.glsl"
#include "../shadow/msm.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray depth_map;
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly image2DArray representation;
layout(location = 0) uniform float u_esm_c;

vec4 represent(float z) {
#if REPRESENTATION == TECHNIQUE_VSM
  return vec4(z, z * z, 0.0, 0.0);  // Donnelly & Lauritzen 2006: the first two moments
#elif REPRESENTATION == TECHNIQUE_ESM
  return vec4(esm_encode(z, u_esm_c), 0.0, 0.0, 0.0);
#else
  vec4 moments = msm_moments(z);  // the moments of u = 2 z - 1 (see msm.glsl)
#if MSM_QUANTIZED
  return msm_quantize(moments);
#else
  return moments;
#endif
#endif
}

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p.xy, textureSize(depth_map, 0).xy))) return;
  imageStore(representation, p, represent(texelFetch(depth_map, p, 0).r));
}
