#pragma once
// GPU time per pass from timestamp queries. A pass may run several times a
// frame (once per light); its time is the sum. Results are read a few frames
// later, so a frame loop never waits for the GPU; a benchmark may wait.
#include <epoxy/gl.h>
#include <array>

#include <chrono>
#include <optional>
#include <string_view>
#include <vector>

#include "penumbra/gl/handle.hpp"

namespace penumbra::gl {

enum class GpuPass {
  ShadowDepth,
  Resolve,
  FusedFilter,  // resolve + Gaussian in one pass (FusedFilterPass)
  FilterHorizontal,
  FilterVertical,
  SatRows,
  SatColumns,
  Mips,               // the filtered map's mip chain (MipChainPass, --shadow-mips)
  DepthHierarchy,     // the depth maps' min/max hierarchy (DepthHierarchyPass, backprojection)
  VirtualMarking,     // virtual shadow maps: the pages the camera's pixels read
  VirtualAllocation,  // virtual shadow maps: allocation and per-page caster culling
  VirtualPages,       // virtual shadow maps: the casters drawn into the listed pages
  GBuffer,
  AmbientOcclusion,
  Lighting,
  Accumulate,     // --accumulate: one sub-frame added to the running sum
  BandwidthCopy,  // the yardstick of `penumbra bench`, not part of a frame
  Count
};

inline constexpr std::array<std::string_view, static_cast<std::size_t>(GpuPass::Count)>
    kGpuPassNames{"shadow depth",
                  "resolve",
                  "resolve+filter (fused)",
                  "filter H",
                  "filter V",
                  "SAT rows",
                  "SAT columns",
                  "mips",
                  "depth min/max",
                  "virtual marking",
                  "virtual allocation",
                  "virtual pages",
                  "G-buffer",
                  "SSAO",
                  "lighting",
                  "accumulate",
                  "copy (yardstick)"};

// Milliseconds per pass (0 for passes that did not run), and the frame's
// total from its first timestamp to its last. With a serializing profiler
// also the wall-clock time between the finished boundaries: the GPU's time
// plus a submission's latency, and the only clock of drivers whose timer
// queries miss work (llvmpipe's stay at 0 across compute dispatches).
struct GpuFrameTimes {
  std::array<double, static_cast<std::size_t>(GpuPass::Count)> pass_ms{};
  std::array<double, static_cast<std::size_t>(GpuPass::Count)> pass_wall_ms{};
  std::array<bool, static_cast<std::size_t>(GpuPass::Count)> ran{};
  double total_ms = 0.0;
  double total_wall_ms = 0.0;
};

class GpuProfiler {
 public:
  // frames_in_flight: how many frames may be recorded before the oldest is
  // read. serialize: finish all GPU work before every timestamp, so each
  // pass is timed alone. A benchmark wants that: drivers may defer work
  // (llvmpipe runs draws only at the next flush), and a timestamp then
  // lands before the work it should follow. A frame loop does not.
  explicit GpuProfiler(int frames_in_flight = 3, bool serialize = false);
  ~GpuProfiler();
  GpuProfiler(const GpuProfiler&) = delete;
  GpuProfiler& operator=(const GpuProfiler&) = delete;

  void begin_frame();
  void begin(GpuPass pass);
  void end(GpuPass pass);
  void end_frame();

  // The oldest recorded frame that is not yet read: nullopt if there is
  // none, or (wait = false) if the GPU has not finished it.
  std::optional<GpuFrameTimes> read(bool wait);

 private:
  static constexpr int kQueriesPerFrame = 128;
  struct Frame {
    std::vector<GLuint> queries;  // kQueriesPerFrame timestamp queries
    std::vector<double> wall_ms;  // wall clock at each query (serializing profilers)
    struct Span {
      GpuPass pass;
      int begin, end;  // indices of its two timestamp queries
    };
    std::vector<Span> spans;
    int used = 0;
    bool pending = false;
  };
  int record(GpuPass pass);

  std::vector<Frame> frames_;
  bool serialize_ = false;
  std::chrono::steady_clock::time_point epoch_ = std::chrono::steady_clock::now();
  int current_ = 0;      // frame being recorded
  int oldest_ = 0;       // next frame to read
  int open_begin_ = -1;  // passes do not nest: one is open at a time
};

// Times one pass for its scope when a profiler is given.
class GpuPassScope {
 public:
  GpuPassScope(GpuProfiler* profiler, GpuPass pass) : profiler_(profiler), pass_(pass) {
    if (profiler_) profiler_->begin(pass_);
  }
  ~GpuPassScope() {
    if (profiler_) profiler_->end(pass_);
  }
  GpuPassScope(const GpuPassScope&) = delete;
  GpuPassScope& operator=(const GpuPassScope&) = delete;

 private:
  GpuProfiler* profiler_;
  GpuPass pass_;
};

}  // namespace penumbra::gl
