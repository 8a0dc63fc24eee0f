// Texel density (--view texel-density): how many shadow-map texels fall
// into one screen pixel's footprint on the receiver, an area ratio (its
// square root is the linear ratio of the pixel's size to a texel's there).
// 1 is the goal of virtual shadow maps: every pixel sees at least one
// texel of its own. Below 1 a texel spans several pixels and the shadow's
// edges alias into blocks; far above 1 texels are wasted.
//
// Both footprints are measured on the receiver's tangent plane: the
// pixel's is the parallelogram between the camera rays through the next
// pixels in x and y (dx, dy); a texel of world size t across the light's
// rays covers t^2 / |cos theta_l| of a receiver tilted by theta_l from
// them. Their ratio is the product of the two axes' aliasing factors of
// Stamminger & Drettakis, "Perspective Shadow Maps", SIGGRAPH 2002, eq. 1
// (perspective aliasing: the texel's size against the pixel's; projective
// aliasing: the cosines).
// Needs shaders/shadow/lookup.glsl and view_select.glsl, and the
// shadow-views block (shadow_views[]).
#pragma once

// The texel of the map that shades a point: its world size across the
// light's rays, and whether that map covers the point at all.
struct ShadingTexel {
  float world_size;
  bool covered;
};

// The texel of the shadow view a pixel's lookup reads for light `light`
// at `world` (camera_depth: the point's depth along the camera's view
// direction): the view select_shadow_view() picks, as the lookups do (a
// spot light's one view, the cube face, the cascade; in a cascade's blend
// band the nearer cascade, which is weighted the most over the band).
// This is the one place that says which map texel shades a pixel: a
// shadow-map layout with another choice of map (a virtual map's clipmap
// level or mip level) supplies its level's texel here.
ShadingTexel shading_texel(GpuLight light, vec3 world, float camera_depth) {
  ViewSelection selected = select_shadow_view(light, world, camera_depth);
  GpuShadowView view = shadow_views[selected.view];
  vec4 clip = view.view_projection * vec4(world, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  bool covered = clip.w > 0.0 && all(greaterThanEqual(uv, vec2(0.0))) &&
                 all(lessThanEqual(uv, vec2(1.0)));
  return ShadingTexel(shadow_texel_world(view, light_linear_depth(view, world)), covered);
}

// Texels per pixel (an area ratio, see above) of a pixel whose footprint
// on the receiver is spanned by dx and dy, on a receiver with unit normal
// `normal`, lit from the unit direction `to_light`, shaded by `texel`;
// 0 where no map covers the point (no texel shades it).
float texels_per_pixel(ShadingTexel texel, vec3 dx, vec3 dy, vec3 normal, vec3 to_light) {
  if (!texel.covered || !(texel.world_size > 0.0)) return 0.0;
  float pixel_area = length(cross(dx, dy));
  // A receiver along the light's rays: a texel's footprint grows without
  // bound; 1e-4 keeps the value finite (and tiny) there.
  float texel_area = texel.world_size * texel.world_size / max(abs(dot(normal, to_light)), 1e-4);
  return pixel_area / texel_area;
}

// The false colour of a density d > 0 on a log2 scale: red at 1/4 or
// less, orange at 1/2, green at 1, cyan at 2, blue at 4 or more
// (docs/rendering.md has the legend); black where d is 0 (no map covers
// the point).
vec3 texel_density_colour(float d) {
  if (!(d > 0.0)) return vec3(0.0);
  const vec3 stops[5] = vec3[](vec3(0.85, 0.1, 0.1), vec3(0.95, 0.6, 0.1), vec3(0.15, 0.75, 0.2),
                               vec3(0.1, 0.75, 0.9), vec3(0.15, 0.25, 0.95));
  float t = clamp(log2(d) + 2.0, 0.0, 4.0);
  int i = min(int(floor(t)), 3);
  return mix(stops[i], stops[i + 1], t - float(i));
}
