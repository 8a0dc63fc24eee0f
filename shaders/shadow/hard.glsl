// Hard shadow: one binary depth test against the nearest texel.
// Returns the fraction of light that arrives: 1 lit, 0 shadowed.

float shadow_hard(sampler2D depth_map, vec2 uv, float receiver_depth, float bias) {
  ivec2 size = textureSize(depth_map, 0);
  ivec2 texel = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
  float occluder = texelFetch(depth_map, texel, 0).r;
  return receiver_depth - bias <= occluder ? 1.0 : 0.0;
}
