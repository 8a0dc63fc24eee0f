#pragma once
// Readers of our own for the two formats large scanned and generated
// meshes come in: Wavefront OBJ and binary PLY. They stream the file
// through a fixed buffer and write straight into the final vertex and
// index arrays, sized from a first count, so a million-triangle model
// reads in a fraction of assimp's time and memory (docs/scenes.md, "Models").
// They read geometry only: a file that uses anything else (OBJ materials,
// lines, curves, PLY properties or elements beyond positions, normals,
// texture coordinates, colours and faces) is left to assimp.
#include <optional>
#include <string>

#include "scene/mesh.hpp"

namespace penumbra {

struct DirectMesh {
  // Vertex::material is 0 and, where the file has none, the normal is
  // zero, uv (0, 0) and the colour white.
  TriangleMesh mesh;
  bool has_normals = false;
  bool has_colors = false;
};

// The mesh of an OBJ file, or nullopt when the file needs assimp. Polygons
// are split as face_triangulation.hpp says. Throws RuntimeError "<path>:
// line N: <what>" for a malformed line (a number that is not one, an
// index of 0 or past the data defined so far, a face of fewer than three
// corners), and "<path>: mesh 0, vertex K: position (...) is not finite".
std::optional<DirectMesh> read_obj_directly(const std::string& path);

// The mesh of a binary little-endian PLY file whose elements are "vertex"
// (float x, y, z; optionally float nx, ny, nz; float u, v or s, t; uchar
// red, green, blue, alpha) and "face" (a list of vertex indices), or
// nullopt when it needs assimp (ASCII, big-endian, other elements or
// types). Throws RuntimeError naming what is wrong: counts the file's
// size cannot hold, an index out of range, a position that is not finite.
std::optional<DirectMesh> read_ply_directly(const std::string& path);

}  // namespace penumbra
