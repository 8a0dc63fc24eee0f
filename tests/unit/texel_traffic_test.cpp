// The bytes each pass over the shadow maps moves per texel, as `penumbra
// bench` counts them: from the passes' formats, tiles and aprons.
#include <gtest/gtest.h>

#include "penumbra/filter/gaussian_blur_pass.hpp"
#include "penumbra/filter/summed_area_table_pass.hpp"
#include "penumbra/filter/texture_copy_pass.hpp"
#include "penumbra/shadow/moment_resolve_pass.hpp"
#include "render/device_bandwidth.hpp"
#include "render/pass_timing.hpp"
#include "shared/filter_tiles.h"

namespace penumbra {
namespace {

using gl::GpuPass;

// The resolve reads one 32-bit depth and writes the representation: msm
// RGBA32F 16 bytes, msm16 RGBA16 8, vsm RG32F 8, esm R32F 4.
TEST(TexelTraffic, ResolveWritesTheRepresentationsFormat) {
  const GLenum depth = GL_DEPTH_COMPONENT32F;
  for (auto [technique, bytes] : {std::pair{Technique::Msm, 16.0}, std::pair{Technique::Msm16, 8.0},
                                  std::pair{Technique::Vsm, 8.0}, std::pair{Technique::Esm, 4.0}}) {
    const TexelTraffic t = MomentResolvePass::texel_traffic(depth, technique);
    EXPECT_EQ(t.read, 4.0);
    EXPECT_EQ(t.written, bytes);
  }
}

// A Gaussian pass reads each texel (1 + 2 W / tile) times with its apron,
// and writes it once: msm's RGBA32F at W = 8 reads 1.25 x 16 = 20 bytes;
// over a map that the tiles do not divide, the overhanging tiles' clamped
// reads count too.
TEST(TexelTraffic, GaussianReadsTheApron) {
  ASSERT_EQ(GAUSSIAN_TILE_ALONG, 64);
  ASSERT_EQ(GAUSSIAN_TILE_ACROSS, 8);
  for (int axis : {0, 1}) {
    const TexelTraffic msm = GaussianBlurPass::texel_traffic(GL_RGBA32F, 8, axis, 2048, 2048);
    EXPECT_DOUBLE_EQ(msm.read, (1.0 + 16.0 / 64.0) * 16.0);
    EXPECT_EQ(msm.written, 16.0);
    const TexelTraffic msm16 = GaussianBlurPass::texel_traffic(GL_RGBA16, 4, axis, 1024, 512);
    EXPECT_DOUBLE_EQ(msm16.read, (1.0 + 8.0 / 64.0) * 8.0);
    EXPECT_EQ(msm16.written, 8.0);
  }
  // 100 x 20 along x: 2 tiles of 64 + 2 x 3 along, 3 tiles of 8 rows
  // across.
  const TexelTraffic odd = GaussianBlurPass::texel_traffic(GL_R32F, 3, 0, 100, 20);
  EXPECT_DOUBLE_EQ(odd.read, 4.0 * (2 * 70) * (3 * 8) / (100.0 * 20.0));
  EXPECT_DOUBLE_EQ(GaussianBlurPass::texel_traffic(GL_R32F, 3, 1, 20, 100).read, odd.read);
}

// The summed-area table's row scan reads the representation and writes
// the integer table with as many channels; the column scan reads and
// writes the table.
TEST(TexelTraffic, SummedAreaTableScansTheIntegerTable) {
  EXPECT_EQ(SummedAreaTablePass::row_traffic(GL_RGBA32F).read, 16.0);
  EXPECT_EQ(SummedAreaTablePass::row_traffic(GL_RGBA32F).written, 16.0);  // RGBA32UI
  EXPECT_EQ(SummedAreaTablePass::row_traffic(GL_RGBA16).read, 8.0);
  EXPECT_EQ(SummedAreaTablePass::row_traffic(GL_RGBA16).written, 16.0);
  EXPECT_EQ(SummedAreaTablePass::row_traffic(GL_RG32F).written, 8.0);  // RG32UI
  EXPECT_EQ(SummedAreaTablePass::column_traffic(GL_R32F).read, 4.0);   // R32UI
  EXPECT_EQ(SummedAreaTablePass::column_traffic(GL_R32F).written, 4.0);
  EXPECT_EQ(TextureCopyPass::texel_traffic(GL_DEPTH_COMPONENT32F).total(), 8.0);
  EXPECT_EQ(TextureCopyPass::texel_traffic(GL_RGBA32F).total(), 32.0);
}

double frame_total(const ShadowSettings& s, int size) {
  double total = 0.0;
  const auto traffic = shadow_map_traffic(s, size, size);
  for (GpuPass pass : {GpuPass::Resolve, GpuPass::FusedFilter, GpuPass::FilterHorizontal,
                       GpuPass::FilterVertical, GpuPass::SatRows, GpuPass::SatColumns}) {
    if (const auto& t = traffic[static_cast<std::size_t>(pass)]) total += t->total();
  }
  return total;
}

// A frame's filtering, resolve to filtered map, per texel at W = 8 on a
// 2048^2 map: msm 20 + 2 x 36 = 92 bytes, msm16 12 + 2 x 18 = 48, vsm 48,
// esm 26; msm through the SAT 20 + 32 + 32 = 84. Only the passes that run
// are counted: a hard shadow has only the copy's.
TEST(TexelTraffic, FrameTotalsFollowTheTechniqueAndFilter) {
  ShadowSettings s;
  s.blur = 8;
  s.filter = Filter::Gaussian;
  s.fused = false;  // the resolve, then the horizontal and vertical passes
  const std::pair<Technique, double> expected[] = {{Technique::Msm, 92.0},
                                                   {Technique::Msm16, 48.0},
                                                   {Technique::Vsm, 48.0},
                                                   {Technique::Esm, 26.0}};
  for (auto [technique, bytes] : expected) {
    s.technique = technique;
    EXPECT_DOUBLE_EQ(frame_total(s, 2048), bytes) << static_cast<int>(technique);
  }
  // Fused: the depth under each 32-wide tile and its apron, read once, and
  // the representation written once. msm at W = 8 takes 16-row tiles in
  // 32 KiB: (48 x 32) / (32 x 16) x 4 + 16 = 28 bytes; msm16 at W = 4,
  // 32-row tiles: (40 / 32)^2 x 4 + 8 = 14.25 (Peters 2017: about 14-16).
  s.fused = true;
  s.technique = Technique::Msm;
  EXPECT_DOUBLE_EQ(frame_total(s, 2048), 28.0);
  s.technique = Technique::Msm16;
  s.blur = 4;
  EXPECT_DOUBLE_EQ(frame_total(s, 2048), 14.25);
  const auto fused = shadow_map_traffic(s, 2048, 2048);
  EXPECT_FALSE(fused[static_cast<std::size_t>(GpuPass::Resolve)]);
  EXPECT_FALSE(fused[static_cast<std::size_t>(GpuPass::FilterHorizontal)]);
  s.blur = 8;
  s.technique = Technique::Msm;
  s.filter = Filter::Sat;
  EXPECT_DOUBLE_EQ(frame_total(s, 2048), 84.0);
  const auto sat = shadow_map_traffic(s, 2048, 2048);
  EXPECT_FALSE(sat[static_cast<std::size_t>(GpuPass::FilterHorizontal)]);
  s.technique = Technique::Hard;
  const auto hard = shadow_map_traffic(s, 2048, 2048);
  EXPECT_FALSE(hard[static_cast<std::size_t>(GpuPass::Resolve)]);
  EXPECT_FALSE(hard[static_cast<std::size_t>(GpuPass::ShadowDepth)]);
  EXPECT_EQ(hard[static_cast<std::size_t>(GpuPass::BandwidthCopy)]->total(), 8.0);
}

// Known NVIDIA boards by their GL_RENDERER name, the more specific name
// first; the bus suffix ("/PCIe/SSE2", on SXM boards too) is not the
// board's name; other renderers have no figure.
TEST(DeviceBandwidth, KnownNvidiaParts) {
  EXPECT_EQ(known_device_bandwidth("NVIDIA H200/PCIe/SSE2")->gb_per_second, 4800.0);
  EXPECT_EQ(known_device_bandwidth("NVIDIA H100 80GB HBM3/PCIe/SSE2")->gb_per_second, 3350.0);
  EXPECT_EQ(known_device_bandwidth("NVIDIA H100 PCIe/PCIe/SSE2")->gb_per_second, 2000.0);
  EXPECT_EQ(known_device_bandwidth("NVIDIA L40S/PCIe/SSE2")->gb_per_second, 864.0);
  EXPECT_EQ(known_device_bandwidth("NVIDIA L4/PCIe/SSE2")->gb_per_second, 300.0);
  EXPECT_EQ(known_device_bandwidth("NVIDIA A100-SXM4-80GB/PCIe/SSE2")->gb_per_second, 2039.0);
  EXPECT_EQ(known_device_bandwidth("NVIDIA GeForce RTX 4090/PCIe/SSE2")->gb_per_second, 1008.0);
  EXPECT_FALSE(known_device_bandwidth("NVIDIA GH200 480GB/PCIe/SSE2"));  // two memory variants
  EXPECT_FALSE(known_device_bandwidth("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_FALSE(known_device_bandwidth("AMD Radeon Pro W7900 (radeonsi, navi31, LLVM 15.0.6)"));
}

// The summed-area table scans in parallel on a GPU, one thread per line on
// a CPU rasterizer (where barriers are dear).
TEST(SatScan, ParallelOnAGpuSerialOnTheCpu) {
  EXPECT_EQ(preferred_sat_scan("NVIDIA H100 80GB HBM3/PCIe/SSE2"), SatScan::Parallel);
  EXPECT_EQ(preferred_sat_scan("AMD Radeon RX 7900 XTX (radeonsi, navi31)"), SatScan::Parallel);
  EXPECT_EQ(preferred_sat_scan("llvmpipe (LLVM 15.0.6, 256 bits)"), SatScan::Serial);
}

}  // namespace
}  // namespace penumbra
