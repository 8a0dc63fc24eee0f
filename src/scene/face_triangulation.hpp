#pragma once
// Polygons of OBJ and PLY files split into triangles, as the direct
// readers (obj_reader.hpp, ply_reader.hpp) need it: without assimp's
// whole-mesh post-processing step, and with the same triangles it makes
// for triangles and quads.
#include <cstdint>
#include <span>
#include <vector>

#include "scene/mesh.hpp"

namespace penumbra {

// Appends the triangles of the face whose corners are `corners` (indices
// into `vertices`, in order around the face). A triangle is kept as it
// is; a quad is split from its concave corner if it has one (else from
// its first), as assimp's Triangulate step splits it; a larger polygon is
// split into a fan from its first corner, which is right for convex
// polygons only. Returns false, appending nothing, for a polygon of more
// than four corners that is not convex (left to assimp's ear clipping),
// and for fewer than three corners.
bool append_face_triangles(std::span<const std::uint32_t> corners,
                           const std::vector<Vertex>& vertices,
                           std::vector<std::uint32_t>& indices);

}  // namespace penumbra
