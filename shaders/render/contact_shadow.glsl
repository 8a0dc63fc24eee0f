// Screen-space contact shadows: a short march from the shaded point
// towards the light through the camera's depth buffer, for the occluders
// no shadow map resolves (creases, the foot of a model, thin contact
// lines), where the map's bias and texel size let light under. As the
// engines do it (Unreal's and Frostbite's contact shadows; Filament's
// screenSpaceContactShadow): a fixed number of steps over a short
// world-space length, the start dithered per pixel, and a depth thickness
// behind which a surface seen in front of the ray no longer hides it.
// Unlike theirs, a step behind a surface counts only where the ray went
// into it (contact_went_into_surface()): the engines' thickness takes
// every blocker for solid, and thin ones (fence rails, leaf cards) cast
// contact shadows where the ray passes behind them.
//
// The including shader provides the G-buffer's samplers and
// world_position(), the one reconstruction of a position from the depth
// buffer: the march compares distances from the camera in world units,
// never raw depth values, so it holds whatever the depth convention.
#pragma once

vec3 world_position(ivec2 pixel, float depth);

// The surface the depth buffer holds at pixel q, seen along the camera's
// ray towards `point`: how far in front of `point` it lies (negative:
// behind it), and by how much that may be off.
struct ContactSurface {
  float in_front;
  float uncertainty;
};

// The surface is taken on its triangle's plane through the point the
// depth buffer holds at q (world_position()), where the camera's ray
// towards `point` meets it: exact for flat receivers whatever the
// sub-pixel position of `point` (a texel's depth is its centre's), so a
// receiver does not shadow itself at grazing views. Near an edge the
// plane is extended past its triangle by up to the 0.71 pixels between a
// pixel's centre and its corners, which moves it along the ray by that
// many pixel widths times the tangent of the angle between the ray and
// the plane's normal. The uncertainty is a quarter pixel's worth (and a
// hair for rounding): the whole 0.71 dropped the far end of a thin slab's
// contact shadow (192x108, a 2 cm slab under an 8-degree spot light: RMSE
// 0.125 -> 0.208 against the traced reference), and contact_behind()'s
// neighbours catch the silhouettes it was for. Where the plane is seen
// (nearly) edge-on, the pixel's own point along the ray is taken, with
// the tangent at its cap.
ContactSurface contact_surface(ivec2 q, vec3 point) {
  vec3 camera = frame.camera_position.xyz;
  vec3 surface = world_position(q, texelFetch(gbuffer_depth, q, 0).r);
  vec3 plane_normal = normalize(texelFetch(gbuffer_facet, q, 0).xyz);
  vec3 ray = point - camera;
  float distance_to_point = length(ray);
  vec3 direction = ray / distance_to_point;
  // A pixel's world width at that distance (frame.projection[1][1] is
  // 1 / tan(half the vertical field of view)).
  float pixel_width = 2.0 * distance_to_point / (frame.projection[1][1] * frame.viewport.y);
  float cos_angle = abs(dot(plane_normal, direction));
  float seen_at = dot(surface - camera, direction);
  if (cos_angle > 0.1) {
    float on_plane = dot(plane_normal, surface - camera) / dot(plane_normal, direction);
    if (on_plane > 0.0) seen_at = on_plane;
  }
  float tangent = sqrt(max(1.0 - cos_angle * cos_angle, 0.0)) / max(cos_angle, 0.1);
  return ContactSurface(distance_to_point - seen_at,
                        0.25 * pixel_width * tangent + 1e-4 * distance_to_point);
}

// Whether `point` lies behind the surface seen at pixel q, along the
// camera's ray through it, by more than that surface's uncertainty and
// less than the thickness. Background hides nothing.
bool contact_behind(ivec2 q, vec3 point, out ContactSurface surface) {
  surface = ContactSurface(0.0, 0.0);
  if (texelFetch(gbuffer_normal, q, 0).w == 0.0) return false;
  surface = contact_surface(q, point);
  return surface.in_front > surface.uncertainty && surface.in_front < frame.contact_thickness;
}

// The surface the depth buffer holds at the pixel `point` falls in, as
// contact_surface() takes it, and that pixel; false off screen and on
// background, where the buffer holds none.
bool contact_surface_at(vec3 point, out ContactSurface surface, out ivec2 q) {
  surface = ContactSurface(0.0, 0.0);
  q = ivec2(0);
  vec4 clip = frame.projection * frame.view * vec4(point, 1.0);
  if (clip.w <= 0.0) return false;
  vec2 size = frame.viewport.xy;
  vec2 window = (clip.xy / clip.w * 0.5 + 0.5) * size;
  if (any(lessThan(window, vec2(0.0))) || any(greaterThanEqual(window, size))) return false;
  q = ivec2(window);
  if (texelFetch(gbuffer_normal, q, 0).w == 0.0) return false;
  surface = contact_surface(q, point);
  return true;
}

// Whether the march's ray, from `outside` (a point the depth buffer shows
// in front of its surface) to `inside` (one it shows behind its surface),
// went into a surface the buffer holds. A step behind a surface has left
// the space the camera sees empty, and that alone proves no occluder: the
// ray may pass behind a thin one (under the foliage scene's fence rails,
// 2 cm deep, or behind its leaf cards, which have no depth at all), where
// a depth thickness took solid matter for granted. It proves one where the
// ray left that space through a surface: bisected down to a sixteenth of
// the way, the first point found behind lies on the surface seen there
// (within a pixel's worth of its slope, four times contact_surface()'s
// quarter pixel, and the last interval), and the last point found in
// front of the buffer lies in front of that surface too: the ray crossed
// it between the two. Through a silhouette instead, the ray passing
// behind the edge of a nearer object, both points lie behind the nearer
// surface, by the gap between them (the foliage scene's ground seen
// between the fence's slats, its rays rising just behind them: without
// the second test a dozen pixels of the slats' penumbra went black, RMSE
// 0.0273 -> 0.0286). The surface crossed need not be the one seen at
// `inside` (a ray into a thin slab's lit side, seen from above, has its
// next step seen through the top). It must be opaque: a cut-out's depth
// holds its mask's coverage at the pixel's centre only, and the point
// crossed lies elsewhere in the pixel.
bool contact_went_into_surface(vec3 outside, vec3 inside) {
  ContactSurface at;
  ivec2 q;
  for (int i = 0; i < 4; ++i) {
    vec3 middle = 0.5 * (outside + inside);
    if (contact_surface_at(middle, at, q) && at.in_front > at.uncertainty) {
      inside = middle;
    } else {
      outside = middle;
    }
  }
  if (!contact_surface_at(inside, at, q) || texelFetch(gbuffer_specular, q, 0).a < 0.5 ||
      at.in_front > 4.0 * at.uncertainty + 2.0 * distance(inside, outside)) {
    return false;
  }
  ContactSurface before = contact_surface(q, outside);
  return before.in_front <= before.uncertainty;
}

// The part of a source that lies above the horizon of the shading normal
// n, as a disc of directions again: its centre `to_light` and the tangent
// of its angular radius `source_tan`, changed in place. Only that part
// sends the point light (the traced reference gives what lies below the
// horizon no weight, occluded or not), so the march looks for occluders
// of that part. A disc whose centre lies at an elevation e above the
// horizon, less than its radius r, shows the span of elevations from 0 to
// e + r: the march aims at its middle, (e + r) / 2, as wide as half of it.
// Aimed at the centre, the march of a surface the centre lies just below
// (the default scene's box under an 8.45-degree sun, lit over the horizon
// by the disc's upper half) went into the surface itself, which hid the
// centre from every step: the whole face black where the reference
// lights it (backprojection's RMSE 0.0101 -> 0.111). False where no part
// of the source is above the horizon.
bool contact_visible_source(vec3 n, inout vec3 to_light, inout float source_tan) {
  float radius = atan(source_tan);
  float elevation = asin(clamp(dot(n, to_light), -1.0, 1.0));
  if (elevation >= radius) return true;
  if (elevation + radius <= 0.0) return false;
  vec3 along = to_light - dot(n, to_light) * n;  // not 0: the elevation is under 90 degrees
  float middle = 0.5 * (elevation + radius);
  to_light = cos(middle) * normalize(along) + sin(middle) * n;
  source_tan = tan(middle);
  return true;
}

// Fraction of the light that the march lets through from `start` (the
// shaded point, lifted as the light's shadow lookups are, with shading
// normal n) towards the source seen from it in the unit direction
// `to_light`, at most `reach` world units (a spot or point light's
// distance): 1 where nothing is met. `source_tan` is the tangent of the
// source's angular radius seen from the point (0: a point source). The
// march aims at the part of the source above n's horizon
// (contact_visible_source()).
//
// A step behind a surface finds an occluder of the source's centre. The
// surface's point on the camera's ray through the step lies at an angle
// a = h / s off the march (h its distance from the march's line, s the
// step's distance from the start): the occluder spans at least from the
// centre to a, so it hides about 1/2 + a / (2 r) of a source of angular
// radius r (linear between half of it, a blocker's edge on the ray, and
// all of it, a >= r); a point source is hidden whole. That keeps the
// march from cutting hard edges into the penumbrae the technique draws.
// The most hidden over the steps is kept, and an occluder met at a
// fraction t of the march hides 1 - smoothstep(0.5, 1, t) of that: the
// march's end fades instead of cutting a line where its length runs out.
float contact_lit_fraction(ivec2 pixel, vec3 start, vec3 n, vec3 to_light, float reach,
                           float source_tan) {
  float len = min(frame.contact_length, reach);
  int steps = frame.contact_steps;
  if (!(len > 0.0) || steps <= 0) return 1.0;
  if (!contact_visible_source(n, to_light, source_tan)) return 1.0;
  mat4 view_projection = frame.projection * frame.view;
  vec2 size = frame.viewport.xy;
  vec3 camera = frame.camera_position.xyz;
  // Filament's dither: the first step at 1/2 to 3/2 of a step from the
  // start, a different offset in each pixel (shaders/shadow/noise.glsl),
  // which turns the steps' banding into fine noise.
  float dt = 1.0 / float(steps);
  float t = dt * (0.5 + interleaved_gradient_noise(vec2(pixel) + vec2(17.0, 59.0)));
  float hidden = 0.0;
  // The last point of the march the buffer shows in front of its surface,
  // and whether a step behind a surface since was tested: the first one
  // brackets where the ray left the space the camera sees empty; a later
  // one behind the same stretch would bisect the same way.
  vec3 outside = start;
  bool tested = false;
  for (int k = 0; k < steps && hidden < 1.0; ++k, t += dt) {
    vec3 point = start + to_light * (t * len);
    vec4 clip = view_projection * vec4(point, 1.0);
    if (clip.w <= 0.0) break;  // behind the camera: the buffer holds nothing there
    vec2 window = (clip.xy / clip.w * 0.5 + 0.5) * size;
    if (any(lessThan(window, vec2(0.0))) || any(greaterThanEqual(window, size))) break;
    ivec2 q = ivec2(window);
    if (q == pixel) continue;
    // Behind the surface seen at q, and at the pixels nearest the step
    // beside q in x and in y: a step within a pixel of a silhouette lies
    // behind it in the buffer while it passes over the surface in truth
    // (over the edge of a lit top, beside a thin pole); there a neighbour
    // across the edge sees past it.
    ContactSurface surface, beside;
    if (!contact_behind(q, point, surface)) {
      if (surface.in_front <= surface.uncertainty) {
        outside = point;
        tested = false;
      }
      continue;
    }
    ivec2 side = ivec2(sign(window - (vec2(q) + 0.5)));
    ivec2 last = ivec2(size) - 1;
    if (tested || !contact_behind(clamp(q + ivec2(side.x, 0), ivec2(0), last), point, beside) ||
        !contact_behind(clamp(q + ivec2(0, side.y), ivec2(0), last), point, beside)) {
      continue;
    }
    tested = true;
    if (!contact_went_into_surface(outside, point)) continue;
    float part = 1.0;
    if (source_tan > 0.0) {
      vec3 off_march = normalize(camera - point) * surface.in_front;
      off_march -= dot(off_march, to_light) * to_light;
      float a = length(off_march) / (t * len);
      part = 0.5 + 0.5 * min(a / source_tan, 1.0);
    }
    hidden = max(hidden, part * (1.0 - smoothstep(0.5, 1.0, t)));
  }
  return 1.0 - hidden;
}
