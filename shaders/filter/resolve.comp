// Resolve: the light's depth map (z-bar) -> the technique's filterable
// representation (shadow/representation.glsl). REPRESENTATION is the
// TECHNIQUE_* of a filterable technique; MSM_QUANTIZED (0/1) whether the
// moments are stored in the quantization basis (see
// uses_quantized_moments()); IMAGE_FORMAT the matching image format. Every
// layer of the depth-map array (one per shadow view) at once: workgroup z
// is the layer.
//
// SAMPLES (1, 2, 4, 8; --shadow-msaa): the depth maps' samples per texel.
// Above 1 each sample's representation is expanded and the texel stores
// their mean, the fraction of the texel each depth covers weighting its
// moments, so a caster's edge is antialiased before any filter (seed 002's
// multisampled depth buffer).
#include "../shared/bindings.h"
#include "../shadow/representation.glsl"

#ifndef SAMPLES
#define SAMPLES 1
#endif

layout(local_size_x = 16, local_size_y = 16) in;

#if SAMPLES > 1
layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DMSArray depth_map;
#else
layout(binding = UNIT_COMPUTE_INPUT) uniform sampler2DArray depth_map;
#endif
layout(IMAGE_FORMAT, binding = IMAGE_OUTPUT) uniform writeonly image2DArray representation;
layout(location = 0) uniform float u_esm_c;
layout(location = 1) uniform float u_evsm_positive;
layout(location = 2) uniform float u_evsm_negative;
// The first layer of the run this dispatch resolves (filter/layer_runs.hpp).
layout(location = 3) uniform int u_first_layer;

void main() {
  const RepresentationConstants constants =
      RepresentationConstants(u_esm_c, u_evsm_positive, u_evsm_negative);
  const ivec3 p = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, u_first_layer);
#if SAMPLES > 1
  if (any(greaterThanEqual(p.xy, textureSize(depth_map).xy))) return;
  REPRESENTATION_TYPE sum = REPRESENTATION_TYPE(0.0);
  for (int i = 0; i < SAMPLES; ++i) {
    const float z = texelFetch(depth_map, p, i).r;
    sum += representation_expand(representation_stage(z, constants), constants);
  }
  imageStore(representation, p, representation_store(sum * (1.0 / float(SAMPLES))));
#else
  if (any(greaterThanEqual(p.xy, textureSize(depth_map, 0).xy))) return;
  const float z = texelFetch(depth_map, p, 0).r;
  imageStore(representation, p,
             representation_store(representation_expand(representation_stage(z, constants), constants)));
#endif
}
