// --shadow-msaa above 1: one layer of the multisampled z-bar maps resolved
// to the one depth per texel that hard, pcf, pcss, backprojection and the
// blocker search of --soft read: the nearest of the texel's samples. A
// binary depth test cannot average coverage, and the nearest depth keeps
// every caster a sample saw (a thin caster between texel centres still
// casts); a mean of depths would invent a surface half-way between the
// caster and what lies behind it. The filterable techniques average the
// samples' moments instead (filter/resolve.comp, filter/fused_filter.comp).
layout(binding = 0) uniform sampler2DMSArray u_depth;
layout(location = 0) uniform int u_layer;

void main() {
  const ivec3 p = ivec3(gl_FragCoord.xy, u_layer);
  float nearest = texelFetch(u_depth, p, 0).r;
  for (int i = 1; i < textureSamples(u_depth); ++i) nearest = min(nearest, texelFetch(u_depth, p, i).r);
  gl_FragDepth = nearest;
}
