#pragma once
// A one-line progress bar on stderr, drawn only when stderr is a terminal
// and the work has run for more than a second (so scripts and short runs
// see nothing).
#include <chrono>
#include <string>

namespace penumbra {

class ProgressBar {
 public:
  ProgressBar(std::string label, long total);
  ~ProgressBar();  // ends the line if one was drawn
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // Marks `done` of `total` finished; `item` names what is being worked on.
  void update(long done, const std::string& item = {});

 private:
  std::string label_;
  long total_;
  bool terminal_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace penumbra
