#include "core/light_sampling.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra {

namespace {

// A pseudo-random permutation of [0, l) chosen by p: a hash that is a
// bijection on the next power of two, cycle-walked until it lands below l
// (Kensler 2013, Listing 3).
std::uint32_t permute(std::uint32_t i, std::uint32_t l, std::uint32_t p) {
  std::uint32_t w = l - 1;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  do {
    i ^= p;
    i *= 0xe170893du;
    i ^= p >> 16;
    i ^= (i & w) >> 4;
    i ^= p >> 8;
    i *= 0x0929eb3fu;
    i ^= p >> 23;
    i ^= (i & w) >> 1;
    i *= 1u | p >> 27;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5;
  } while (i >= l);
  return (i + p) % l;
}

// A hash of (i, p) as a float in [0, 1) (Kensler 2013, Listing 4).
float randfloat(std::uint32_t i, std::uint32_t p) {
  i ^= p;
  i ^= i >> 17;
  i ^= i >> 10;
  i *= 0xb36534e5u;
  i ^= i >> 12;
  i ^= i >> 21;
  i *= 0x93fc4795u;
  i ^= 0xdf6e307fu;
  i ^= i >> 17;
  i *= 1u | p >> 18;
  return static_cast<float>(static_cast<double>(i) / 4294967808.0);
}

// The pattern-dependent seeds of Kensler's Listing 6.
struct CmjSeeds {
  std::uint32_t order, column, row, jitter_x, jitter_y;
  explicit CmjSeeds(std::uint32_t pattern)
      : order(pattern * 0x51633e2du),
        column(pattern * 0x68bc21ebu),
        row(pattern * 0x02e5be93u),
        jitter_x(pattern * 0x967a889bu),
        jitter_y(pattern * 0x368cc8b7u) {}
};

// The grid of n points: m columns (floor(sqrt(n))) and ceil(n / m) rows.
std::uint32_t cmj_columns(std::uint32_t n) {
  return static_cast<std::uint32_t>(std::sqrt(static_cast<double>(n)));
}

// Point s (in stratum order) whose column and row strata were permuted to
// sx and sy; one expression for cmj_sample and CmjPointSet, so the two
// round alike.
glm::vec2 cmj_point(std::uint32_t s, std::uint32_t sx, std::uint32_t sy, std::uint32_t n,
                    std::uint32_t m, std::uint32_t rows, const CmjSeeds& seeds) {
  const float jx = randfloat(s, seeds.jitter_x);
  const float jy = randfloat(s, seeds.jitter_y);
  const float x =
      (static_cast<float>(sx) + (static_cast<float>(sy) + jx) / static_cast<float>(rows)) /
      static_cast<float>(m);
  const float y = (static_cast<float>(s) + jy) / static_cast<float>(n);
  // Float rounding can reach 1 exactly; the square is half-open.
  return glm::min(glm::vec2(x, y), glm::vec2(1.0f - 0x1p-24f));
}

}  // namespace

glm::vec2 cmj_sample(std::uint32_t s, std::uint32_t n, std::uint32_t pattern) {
  // Kensler 2013, Listing 6: any n, aspect ratio 1.
  const std::uint32_t m = cmj_columns(n);
  const std::uint32_t rows = (n + m - 1) / m;
  const CmjSeeds seeds(pattern);
  s = permute(s, n, seeds.order);
  const std::uint32_t sx = permute(s % m, m, seeds.column);
  const std::uint32_t sy = permute(s / m, rows, seeds.row);
  return cmj_point(s, sx, sy, n, m, rows, seeds);
}

void CmjPointSet::generate(std::uint32_t n, std::uint32_t pattern) {
  const std::uint32_t m = cmj_columns(n);
  const std::uint32_t rows = (n + m - 1) / m;
  const CmjSeeds seeds(pattern);
  column_.resize(m);
  row_.resize(rows);
  for (std::uint32_t i = 0; i < m; ++i) column_[i] = permute(i, m, seeds.column);
  for (std::uint32_t i = 0; i < rows; ++i) row_[i] = permute(i, rows, seeds.row);
  points_.resize(n);
  // cmj_sample's s runs over every stratum 0 .. n-1 once whatever the
  // first permutation does; here it runs in order, so s / m and s % m
  // step through the rows and columns.
  std::uint32_t s = 0;
  for (std::uint32_t r = 0; r < rows && s < n; ++r) {
    for (std::uint32_t c = 0; c < m && s < n; ++c, ++s) {
      points_[s] = cmj_point(s, column_[c], row_[r], n, m, rows, seeds);
    }
  }
}

SquareCell square_cell(std::uint32_t index, std::uint32_t n) {
  SquareCell cell;
  cell.columns = cmj_columns(n);
  const std::uint32_t fewer = n / cell.columns;  // cells of the narrower columns
  const std::uint32_t wider = n % cell.columns;  // columns of fewer + 1 cells, first
  const std::uint32_t in_wider = wider * (fewer + 1);
  std::uint32_t before = 0;  // cells of the columns to the left
  if (index < in_wider) {
    cell.rows = fewer + 1;
    cell.column = index / cell.rows;
    before = cell.column * cell.rows;
  } else {
    cell.rows = fewer;
    cell.column = wider + (index - in_wider) / cell.rows;
    before = in_wider + (cell.column - wider) * cell.rows;
  }
  cell.row = index - before;
  const auto nf = static_cast<float>(n), rows = static_cast<float>(cell.rows);
  cell.origin = {static_cast<float>(before) / nf, static_cast<float>(cell.row) / rows};
  cell.size = {rows / nf, 1.0f / rows};
  return cell;
}

CellSample stratified_sample(std::uint32_t k, std::uint32_t n, std::uint32_t pattern) {
  const CmjSeeds seeds(pattern);
  const std::uint32_t s = permute(k, n, seeds.order);
  CellSample sample;
  sample.cell = square_cell(s, n);
  const SquareCell& c = sample.cell;
  // The column's cells take distinct 1/n-wide sub-columns of it (each
  // column its own permutation), the column's m sub-rows of their cells
  // one each across the columns.
  const std::uint32_t sub_column = permute(c.row, c.rows, seeds.column + c.column * 0x9e3779b9u);
  const std::uint32_t sub_row = permute(c.column, c.columns, seeds.row);
  const float jx = randfloat(s, seeds.jitter_x);
  const float jy = randfloat(s, seeds.jitter_y);
  const float x = c.origin.x + (static_cast<float>(sub_column) + jx) / static_cast<float>(n);
  const float y =
      c.origin.y + (static_cast<float>(sub_row) + jy) / static_cast<float>(c.columns) * c.size.y;
  sample.point = glm::min(glm::vec2(x, y), glm::vec2(1.0f - 0x1p-24f));
  return sample;
}

glm::vec2 concentric_disk(glm::vec2 u) {
  const glm::vec2 a = 2.0f * u - 1.0f;
  if (a.x == 0.0f && a.y == 0.0f) return glm::vec2(0.0f);
  const float quarter_pi = 0.78539816f;
  float r = 0.0f, phi = 0.0f;
  if (std::abs(a.x) > std::abs(a.y)) {
    r = a.x;
    phi = quarter_pi * (a.y / a.x);
  } else {
    r = a.y;
    phi = 2.0f * quarter_pi - quarter_pi * (a.x / a.y);
  }
  return r * glm::vec2(std::cos(phi), std::sin(phi));
}

glm::vec3 uniform_cone(glm::vec2 u, float one_minus_cos_max) {
  return uniform_cone_from_disk(concentric_disk(u), one_minus_cos_max);
}

glm::vec3 uniform_cone_from_disk(glm::vec2 d, float one_minus_cos_max) {
  const float r2 = glm::dot(d, d);
  if (r2 == 0.0f) return glm::vec3(0.0f, 0.0f, 1.0f);
  // 1 - cos(theta) and sin(theta) from it without cancellation:
  // sin^2 = (1 - cos)(1 + cos).
  const float one_minus_cos = r2 * one_minus_cos_max;
  const float cos_theta = 1.0f - one_minus_cos;
  const float sin_theta = std::sqrt(std::max(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
  const glm::vec2 xy = d * (sin_theta / std::sqrt(r2));
  return glm::vec3(xy, cos_theta);
}

}  // namespace penumbra
