// --shadow-msaa above 1 (the filterable techniques): one layer of the
// multisampled z-bar maps resolved to the one depth per texel that the
// blocker search of --soft and the shadow-map view read: the nearest of
// the texel's samples, which keeps every caster a sample saw (a thin
// caster between texel centres still counts as a blocker); a mean of
// depths would invent a surface half-way between the caster and what lies
// behind it. The moments themselves are the samples' mean
// (filter/resolve.comp, filter/fused_filter.comp). The techniques that
// read depth draw one sample instead (depth_samples(): the nearest sample
// grows their shadows by up to half a texel, which measured worse).
layout(binding = 0) uniform sampler2DMSArray u_depth;
layout(location = 0) uniform int u_layer;

void main() {
  const ivec3 p = ivec3(gl_FragCoord.xy, u_layer);
  float nearest = texelFetch(u_depth, p, 0).r;
  for (int i = 1; i < textureSamples(u_depth); ++i) nearest = min(nearest, texelFetch(u_depth, p, i).r);
  gl_FragDepth = nearest;
}
