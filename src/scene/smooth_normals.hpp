#pragma once
// Vertex normals for triangle meshes that come without them (OBJ and PLY
// scans, STL without facet normals, ...).
#include "scene/mesh.hpp"

namespace penumbra {

// Each triangle corner gets the area-weighted mean of the normals of the
// triangles around its position whose normal is within `crease_degrees`
// of its own triangle's: a scan comes out smooth, a box keeps its edges.
// Vertices are found by position (so seams of other attributes do not
// break the smoothing), and corners at one position with equal normals
// (and equal material, texture coordinates and colour) share one vertex
// of the result. A corner whose triangles have no area
// takes the mean of every triangle there, or +y. Vertex::material is the
// corner's own. The result's vertices follow the order in which the
// input's vertices first reach each position. O(n log n) in the vertices,
// no allocation per vertex.
TriangleMesh with_smooth_normals(const TriangleMesh& mesh, float crease_degrees);

}  // namespace penumbra
