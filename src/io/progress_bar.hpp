#pragma once
// A one-line progress bar on stderr for long work. It appears only when
// stderr is a terminal and the work has run for over a second, so short
// runs, pipes and logs stay clean; finish() erases it.
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
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::mutex mutex_;
  std::string label_;
  Clock::time_point start_, last_draw_;
  bool terminal_ = false;
  bool drawn_ = false;
};

}  // namespace penumbra
