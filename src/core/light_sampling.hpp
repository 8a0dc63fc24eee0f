#pragma once
// Stratified points on the unit square for sampling an area light, shared
// by the renderer (--accumulate's source points) and the traced reference
// (its rays), so both sample the same sources the same way:
// correlated multi-jittered sampling (Kensler, "Correlated Multi-Jittered
// Sampling", Pixar Technical Memo 13-01, 2013). For any count N, each of
// the N rows of height 1/N holds one point; where N = m n (m =
// floor(sqrt(N)), n = ceil(N / m): a square, or m (m + 1)), each cell of
// the m x n grid and each of the N columns of width 1/N holds one too.
// Each pattern index gives an independent, deterministic set.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace penumbra {

// Point s (0 <= s < n) of pattern `pattern`'s n points, in [0, 1)^2.
glm::vec2 cmj_sample(std::uint32_t s, std::uint32_t n, std::uint32_t pattern);

// All n points of a pattern at once, for an estimator that sums over all
// of them: the very points cmj_sample gives for s = 0 .. n-1, bit for bit,
// listed stratum by stratum instead of in cmj_sample's shuffled order.
// Listing every stratum makes Kensler's first permutation (which only
// reorders the strata) unnecessary, and his column and row permutations
// are computed once per set (sqrt(n) each) instead of for every point:
// each point then costs two hashes. Reusable: keeps its buffers.
class CmjPointSet {
 public:
  // Fills points() with pattern `pattern`'s n points (n >= 1).
  void generate(std::uint32_t n, std::uint32_t pattern);
  [[nodiscard]] const std::vector<glm::vec2>& points() const { return points_; }

 private:
  std::vector<std::uint32_t> column_, row_;  // the permuted strata
  std::vector<glm::vec2> points_;
};

// A partition of the unit square into n cells of equal area, for any n:
// m = floor(sqrt(n)) columns side by side, the first (n mod m) holding
// ceil(n / m) cells stacked in y and the others floor(n / m); a column of
// c cells is c / n wide, so each of its cells (1 / c high) has area 1 / n.
// Kensler's any-n layout (cmj_sample, one point per 1/n row in y) puts
// points in only some cells of its m x ceil(n / m) grid when n is not
// m ceil(n / m), and two in others; an estimator that spreads each
// point's weight over its cell (the dithered --accumulate of
// shaders/shadow/accumulate.glsl) is then biased. Here every cell is
// sampled exactly once and the cells stay near square (their sides differ
// by at most a factor (m + 2) / m).
struct SquareCell {
  glm::vec2 origin{0.0f};                 // lower corner, in [0, 1)^2
  glm::vec2 size{1.0f};                   // width and height
  std::uint32_t column = 0, columns = 1;  // its column, of the partition's m
  std::uint32_t row = 0, rows = 1;        // its row, of the rows its column holds
};

// Cell `index` (0 <= index < n) of the partition of n, column by column,
// bottom to top.
SquareCell square_cell(std::uint32_t index, std::uint32_t n);

// Sample k (0 <= k < n) of pattern `pattern`'s n stratified samples: as k
// runs over 0 .. n-1 it visits every cell of square_cell's partition once,
// in an order the pattern shuffles (Kensler 2013, Listing 3's
// permutation), and a jittered point in it. The points are multi-jittered
// as Kensler's are (Chiu, Shirley and Wang 1994): in the column of c
// cells, the cells' points fall in distinct 1/n-wide sub-columns, so the
// n points' x coordinates fill the n 1/n-wide columns of the square once;
// and each column's points lie in its own of m sub-rows of their cells.
struct CellSample {
  SquareCell cell;
  glm::vec2 point{0.5f};  // inside cell, in [0, 1)^2
};
CellSample stratified_sample(std::uint32_t k, std::uint32_t n, std::uint32_t pattern);

// A point of the unit disk from a point of the unit square, area-uniform
// and keeping strata apart (Shirley & Chiu, "A Low Distortion Map Between
// Disk and Square", JGT 1997: concentric squares to concentric circles).
glm::vec2 concentric_disk(glm::vec2 u);

// A unit direction uniform in solid angle over the cone of directions
// within angle theta_max of +z, from a point of the unit square; the cone
// is given by 1 - cos(theta_max) (accurate for small cones, where cos is
// 1 to float precision). The disk's area maps to the cone's solid angle in
// proportion (1 - cos(theta) = r^2 (1 - cos(theta_max)); pbrt-v4,
// SampleUniformCone, through the concentric disk), so the square's strata
// stay strata of the cone.
glm::vec3 uniform_cone(glm::vec2 u, float one_minus_cos_max);

// The same from the point d = concentric_disk(u) of the unit disk.
glm::vec3 uniform_cone_from_disk(glm::vec2 d, float one_minus_cos_max);

}  // namespace penumbra
