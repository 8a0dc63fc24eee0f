#pragma once
// A one-line progress bar on stderr for long work. It appears only when
// stderr is a terminal and the work has run for over a second, so short
// runs, pipes and logs stay clean; finish() erases it. Work in named steps
// (step()) shows the step, the count and an estimate of the time left on
// the bar, and when stderr is not a terminal writes one plain line as each
// step begins, so a log shows where the time went.
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>
#include <utility>

namespace penumbra {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // Safe to call from many threads at once; a call that finds another
  // drawing returns at once.
  void update(std::int64_t done, std::int64_t total);
  // The step the work is in from now; `done` of `total` items are done.
  void step(const std::string& name, std::int64_t done, std::int64_t total);
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::mutex mutex_;
  void draw(std::int64_t done, std::int64_t total, Clock::time_point now);
  std::string label_;
  std::string step_;
  std::size_t drawn_width_ = 0;
  Clock::time_point start_, last_draw_;
  bool terminal_ = false;
  bool drawn_ = false;
};

}  // namespace penumbra
