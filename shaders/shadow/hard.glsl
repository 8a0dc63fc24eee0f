// Hard shadow: one binary depth test against the nearest texel of layer
// `layer` of the depth-map array. Returns the fraction of light that
// arrives: 1 lit, 0 shadowed.

float shadow_hard(sampler2DArray depth_maps, int layer, vec2 uv, float receiver_depth, float bias) {
  ivec2 size = textureSize(depth_maps, 0).xy;
  ivec2 texel = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
  float occluder = texelFetch(depth_maps, ivec3(texel, layer), 0).r;
  return receiver_depth - bias <= occluder ? 1.0 : 0.0;
}
