#pragma once
// Summed-area table of a light's map, in 32-bit fixed point with
// wrap-around sums (shaders/filter/sat*.glsl): rows, then columns. Works on
// 2D array textures, one table per layer (shadow view). The scans run in
// parallel along each line (sat_scan.comp); the one-thread-per-line scans
// they replace (sat_rows.comp, sat_columns.comp) stay as the reference
// they equal bit for bit.
#include <map>
#include <string>
#include <string_view>
#include <tuple>

#include "penumbra/gl/gpu_profiler.hpp"
#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/texel_traffic.hpp"

namespace penumbra {

// Largest box (in texels) a lookup differences: a square of width
// 2 kMaxBlur + 1 at a sub-texel position touches 2 kMaxBlur + 2 texels
// along each axis (sat_rectangle_average in shaders/filter/sat.glsl).
inline constexpr double kSatMaxBoxArea = double(2 * kMaxBlur + 2) * double(2 * kMaxBlur + 2);
// Fixed-point scale 2^F: the largest power of two for which a box of
// kSatMaxBoxArea values of at most 1 still sums below 2^32. With kMaxBlur =
// 64 that is 2^17: each value is stored to within 2^-18 (3.8e-6).
double sat_fixed_point_scale();

// How the prefix sums run: a workgroup per few lines scanning tiles in
// parallel, or one thread per line.
enum class SatScan { Parallel, Serial };

// The scan for a GL_RENDERER: parallel on a GPU, where one thread per line
// occupies a few percent of it (8,192 threads for four 2048^2 layers);
// serial on a CPU rasterizer (llvmpipe, softpipe, SwiftShader), where
// those threads already keep every core busy and each workgroup barrier
// of the parallel scan costs a switch of every invocation (there the
// parallel scan measures about 2.5 times slower).
SatScan preferred_sat_scan(std::string_view renderer);

class SummedAreaTablePass {
 public:
  // The scan preferred_sat_scan picks for the current context's renderer.
  SummedAreaTablePass();
  explicit SummedAreaTablePass(SatScan scan) : scan_(scan) {}

  [[nodiscard]] SatScan scan() const { return scan_; }

  // Builds the table of every layer of the 2D array `source` (values in [0, 1]).
  void execute(const gl::Texture& source, gl::GpuProfiler* profiler = nullptr);

  // Per texel of a `source_format` map: the row scan reads the source and
  // writes the table (the integer format with the source's channels); the
  // column scan reads and writes the table.
  static TexelTraffic row_traffic(GLenum source_format);
  static TexelTraffic column_traffic(GLenum source_format);

  // Valid after execute(): an unsigned-integer 2D array.
  [[nodiscard]] const gl::Texture& table() const { return table_; }

  // Box averages of every texel, (2 radius + 1)^2 boxes cropped to the map,
  // read from the table: an RGBA32F 2D array. For views and tests.
  const gl::Texture& box_filtered(int radius);

  // Frees the table and the box averages (execute() and box_filtered()
  // make them again), keeping the programs.
  void release() {
    table_ = gl::Texture();
    box_filtered_ = gl::Texture();
  }

 private:
  // axis: the AXIS define, or -1 for none.
  const gl::Program& program(const char* path, GLenum format, int axis = -1);
  void scan_serial(const gl::Texture& source, GLenum format, gl::GpuProfiler* profiler);
  void scan_parallel(const gl::Texture& source, GLenum format, gl::GpuProfiler* profiler);

  SatScan scan_;
  std::map<std::tuple<std::string, GLenum, int>, gl::Program> programs_;
  gl::Texture table_;
  gl::Texture box_filtered_;
};

}  // namespace penumbra
