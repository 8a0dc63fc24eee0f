// Where a point of a flat triangle lies relative to the smooth surface its
// vertex normals describe, for the shadow lookups of the lighting pass.
//
// Near a terminator a smooth-shaded mesh's flat triangles shadow one
// another where the smooth surface the shading shows would not (the
// "shadow terminator" artefact). Hanika ("Hacking the Shadow Terminator",
// Ray Tracing Gems II, 2021, ch. 4) moves the point to the smooth surface:
// below corner i's tangent plane by h_i, it rises by the barycentric mean
// of h_i n_i. The traced reference starts its shadow rays there
// (src/reference/shadow_ray_tracer.cpp: terminator_lift), so the lookups
// test the same point, against the triangle's own plane (which the shadow
// map holds, unlike the interpolated normal's).
//
// The triangle's corners are read from the scene's buffers by
// gl_PrimitiveID (GpuScene::draw binds them and sets first_index). Where
// the buffers are too large to read (first_index is
// SCENE_CORNERS_UNREADABLE) the point stays on its triangle, whose normal
// then comes from the screen-space derivatives of the position: within
// one triangle they are its plane's.
layout(std430, binding = BINDING_SCENE_VERTICES_SSBO) readonly buffer SceneVerticesBlock {
  float scene_vertices[];  // SCENE_VERTEX_FLOATS per vertex (src/scene/mesh.hpp: Vertex)
};
layout(std430, binding = BINDING_SCENE_INDICES_SSBO) readonly buffer SceneIndicesBlock {
  uint scene_indices[];
};
layout(location = LOCATION_FIRST_INDEX) uniform uint first_index;

vec3 scene_vertex_vec3(uint vertex, uint offset) {
  uint at = vertex * uint(SCENE_VERTEX_FLOATS) + offset;
  return vec3(scene_vertices[at], scene_vertices[at + 1u], scene_vertices[at + 2u]);
}

struct SmoothSurface {
  vec3 facet_normal;  // the triangle's normal, on n's side
  float height;       // how far the point rises along n to the smooth surface
};

// For point p of the fragment's triangle, shaded with normal n (turned to
// the viewer's side for a surface seen from behind; corner normals facing
// away from n are turned likewise). The rise is taken along n: measured on
// the bunny (spot light, --accumulate 64) the full vector and its part
// along n gave the same error.
SmoothSurface smooth_surface(vec3 p, vec3 n) {
  if (first_index == SCENE_CORNERS_UNREADABLE) {
    vec3 d = cross(dFdx(p), dFdy(p));
    float length2 = dot(d, d);
    vec3 facet_normal = length2 > 0.0 ? d * inversesqrt(length2) : n;
    return SmoothSurface(dot(facet_normal, n) < 0.0 ? -facet_normal : facet_normal, 0.0);
  }
  uint first = first_index + 3u * uint(gl_PrimitiveID);
  uint corner_index[3] =
      uint[3](scene_indices[first], scene_indices[first + 1u], scene_indices[first + 2u]);
  vec3 corners[3];
  for (int k = 0; k < 3; ++k) {
    corners[k] = scene_vertex_vec3(corner_index[k], uint(SCENE_VERTEX_POSITION));
  }
  vec3 g = cross(corners[1] - corners[0], corners[2] - corners[0]);
  float area2 = dot(g, g);
  SmoothSurface s = SmoothSurface(n, 0.0);
  if (!(area2 > 0.0)) return s;  // degenerate: no plane of its own
  s.facet_normal = g * inversesqrt(area2);
  if (dot(s.facet_normal, n) < 0.0) s.facet_normal = -s.facet_normal;
  // Barycentric coordinates: the sub-triangles' signed areas over the whole.
  vec3 w = vec3(dot(cross(corners[2] - corners[1], p - corners[1]), g),
                dot(cross(corners[0] - corners[2], p - corners[2]), g),
                dot(cross(corners[1] - corners[0], p - corners[0]), g)) /
           area2;
  vec3 lift = vec3(0.0);
  for (int k = 0; k < 3; ++k) {
    vec3 corner_normal = normalize(scene_vertex_vec3(corner_index[k], uint(SCENE_VERTEX_NORMAL)));
    if (dot(corner_normal, n) < 0.0) corner_normal = -corner_normal;
    float below = dot(corners[k] - p, corner_normal);
    if (below > 0.0) lift += w[k] * below * corner_normal;
  }
  s.height = max(dot(lift, n), 0.0);
  return s;
}
