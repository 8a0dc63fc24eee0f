#pragma once
// Model files the tests write themselves, so that no test depends on a
// download: small meshes in several formats, broken ones, and a large grid.
#include <cstdint>
#include <string>

namespace penumbra::testing {

// Writes `content` to `name` under the tests' output folder (replacing
// it) and returns the path.
std::string write_model_file(const std::string& name, const std::string& content);

// A regular tetrahedron standing on its base (y = 0) with its apex at
// y = kTetrahedronHeight, centred on the y axis, as OBJ text; with
// `material`, it uses material "red" of "<material>" (an MTL file).
inline constexpr float kTetrahedronHeight = 1.0f;
std::string tetrahedron_obj(const std::string& material_file = "");
// The MTL file it names: "red" with Kd 0.8 0.1 0.1, Ks 0.5 0.5 0.5, Ns 50.
std::string red_mtl();

// A cube of side 2 centred on the origin, six quads, as OFF text.
std::string cube_off();

// A (2n)-triangle-per-row grid of n x n quads over [0, 1] x [0, 1] in the
// x-z plane, as a binary little-endian PLY: 2 n^2 triangles.
std::string write_grid_ply(const std::string& name, int n);

}  // namespace penumbra::testing
