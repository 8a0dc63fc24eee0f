// Which of a light's shadow views (penumbra/shadow/shadow_views.hpp) a point
// reads: a spot light's only view; the cube face of a point light that the
// direction from the light falls in; the cascade of a directional light
// that the point's camera depth falls in, blended into the next cascade
// over a band at the end of each (so no seam shows where they meet).
#pragma once

struct ViewSelection {
  int view;     // index into the shadow-views block (= the layer of the map arrays)
  int next;     // the view blended in, or `view` when none
  float blend;  // weight of `next`, in [0, 1]
};

// Face of the cube (0..5: +x, -x, +y, -y, +z, -z) whose axis is the major
// axis of d, as a cube map selects its face (OpenGL 4.5, section 8.13).
// cube_face() in src/shadow/cube_views.cpp is its CPU twin.
int cube_face(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}

// camera_depth: the point's depth along the camera's view direction.
ViewSelection select_shadow_view(GpuLight light, vec3 world, float camera_depth) {
  int first = light.views.x;
  int type = int(light.position_type.w);
  if (type == LIGHT_POINT) {
    int face = first + cube_face(world - light.position_type.xyz);
    return ViewSelection(face, face, 0.0);
  }
  int count = light.views.y;
  if (type != LIGHT_DIRECTIONAL || count <= 1) return ViewSelection(first, first, 0.0);
  int c = 0;
  while (c < count - 1 && camera_depth > light.cascade_end[c]) ++c;
  ViewSelection s = ViewSelection(first + c, first + c, 0.0);
  if (c < count - 1) {
    // The blend band: the last cascade_blend.x of this cascade's depth
    // range (which starts at the camera's near plane for the first).
    float start = c == 0 ? light.cascade_blend.y : light.cascade_end[c - 1];
    float band = light.cascade_blend.x * (light.cascade_end[c] - start);
    if (band > 0.0) {
      float t = (camera_depth - (light.cascade_end[c] - band)) / band;
      if (t > 0.0) {
        s.next = s.view + 1;
        s.blend = min(t, 1.0);
      }
    }
  }
  return s;
}
