// Where a point of a flat triangle lies relative to the smooth surface its
// vertex normals describe, for the shadow lookups of the lighting pass.
//
// Near a terminator a smooth-shaded mesh's flat triangles shadow one
// another where the smooth surface the shading shows would not (the
// "shadow terminator" artefact; Hanika, "Hacking the Shadow Terminator",
// Ray Tracing Gems II, 2021, ch. 4). The rise to the smooth surface is the
// terminator model's (src/reference/terminator_offset.hpp, whose
// smooth_surface_rise this mirrors): Cycles' quadratic patch bounded by
// the corners' tangent planes, along the shading normal. The lighting pass
// applies the part of it each light's direction calls for
// (shaders/render/terminator_offset.glsl), as the traced reference does
// for its rays, so both start from the same point.
//
// The triangle's corners are read from the scene's buffers by
// gl_PrimitiveID (GpuScene::draw binds them and sets first_index). Where
// the buffers are too large to read (first_index is
// SCENE_CORNERS_UNREADABLE) the point stays on its triangle, whose normal
// then comes from the screen-space derivatives of the position: within
// one triangle they are its plane's.
layout(std430, binding = BINDING_SCENE_VERTICES_SSBO) readonly buffer SceneVerticesBlock {
  // SCENE_VERTEX_FLOATS per vertex (src/scene/mesh.hpp: Vertex), read four at a time
  vec4 scene_vertex_quads[];
};
layout(std430, binding = BINDING_SCENE_INDICES_SSBO) readonly buffer SceneIndicesBlock {
  uint scene_indices[];
};
layout(location = LOCATION_FIRST_INDEX) uniform uint first_index;

struct SceneCorner {
  vec3 position;
  vec3 normal;  // as stored (not normalized)
};

// A vertex's position and normal, six consecutive floats, in two vec4
// loads instead of six float loads: a vertex starts at an even float
// (src/render/gpu_scene.cpp asserts it), so the six lie at offset 0 or 2
// of two aligned quads.
SceneCorner scene_corner(uint vertex) {
  uint at = vertex * uint(SCENE_VERTEX_FLOATS) + uint(SCENE_VERTEX_POSITION);
  vec4 a = scene_vertex_quads[at / 4u];
  vec4 b = scene_vertex_quads[at / 4u + 1u];
  return (at & 3u) == 0u ? SceneCorner(a.xyz, vec3(a.w, b.xy))
                         : SceneCorner(vec3(a.zw, b.x), b.yzw);
}

struct SmoothSurface {
  vec3 facet_normal;  // the triangle's normal, on n's side
  float height;       // how far the point rises along n to the smooth surface
};

// For point p of the fragment's triangle, shaded with unit normal n
// (turned to the viewer's side for a surface seen from behind).
SmoothSurface smooth_surface(vec3 p, vec3 n) {
  if (first_index == SCENE_CORNERS_UNREADABLE) {
    vec3 d = cross(dFdx(p), dFdy(p));
    float length2 = dot(d, d);
    vec3 facet_normal = length2 > 0.0 ? d * inversesqrt(length2) : n;
    return SmoothSurface(dot(facet_normal, n) < 0.0 ? -facet_normal : facet_normal, 0.0);
  }
  uint first = first_index + 3u * uint(gl_PrimitiveID);
  // Nine loads: three indices, two quads a corner.
  SceneCorner c0 = scene_corner(scene_indices[first]);
  SceneCorner c1 = scene_corner(scene_indices[first + 1u]);
  SceneCorner c2 = scene_corner(scene_indices[first + 2u]);
  vec3 v0 = c0.position, v1 = c1.position, v2 = c2.position;
  vec3 g = cross(v1 - v0, v2 - v0);
  float area2 = dot(g, g);
  SmoothSurface s = SmoothSurface(n, 0.0);
  if (!(area2 > 0.0)) return s;  // degenerate: no plane of its own
  s.facet_normal = g * inversesqrt(area2);
  if (dot(s.facet_normal, n) < 0.0) s.facet_normal = -s.facet_normal;
  // Barycentric coordinates: the sub-triangles' signed areas over the whole.
  vec3 w = vec3(dot(cross(v2 - v1, p - v1), g), dot(cross(v0 - v2, p - v2), g),
                dot(cross(v1 - v0, p - v0), g)) /
           area2;
  vec3 n0 = normalize(c0.normal);
  vec3 n1 = normalize(c1.normal);
  vec3 n2 = normalize(c2.normal);
  vec3 raw = w.x * n0 + w.y * n1 + w.z * n2;
  // The corners' normals on n's side, all turned at once.
  if (dot(raw, n) < 0.0) {
    n0 = -n0;
    n1 = -n1;
    n2 = -n2;
  }
  // The quadratic patch: zero at the corners, its slopes along the edges
  // those of the corners' normals.
  float a = dot(n2 - n0, v0 - v2);
  float b = dot(n2 - n1, v1 - v2);
  float c = dot(n1 - n0, v1 - v0);
  float quadratic = a * w.x * (w.x - 1.0) + (a + b + c) * w.x * w.y + b * w.y * (w.y - 1.0);
  // Each corner's tangent plane, raised to pass above the other corners.
  float e0 = max(max(dot(v1 - v0, n0), dot(v2 - v0, n0)), 0.0);
  float e1 = max(max(dot(v0 - v1, n1), dot(v2 - v1, n1)), 0.0);
  float e2 = max(max(dot(v0 - v2, n2), dot(v1 - v2, n2)), 0.0);
  float h0 = max(dot(v0 - p, n0) + e0, 0.0);
  float h1 = max(dot(v1 - p, n1) + e1, 0.0);
  float h2 = max(dot(v2 - p, n2) + e2, 0.0);
  float h = max(min(min(h0, h1), h2), 0.5 * quadratic);
  s.height = max(h, 0.0) * length(raw);
  return s;
}
