#include "io/progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace penumbra {

ProgressBar::ProgressBar(std::string label, long total)
    : label_(std::move(label)), total_(std::max(total, 1L)), terminal_(isatty(STDERR_FILENO) != 0) {}

ProgressBar::~ProgressBar() {
  if (drawn_) std::fprintf(stderr, "\n");
}

void ProgressBar::update(long done, const std::string& item) {
  if (!terminal_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < std::chrono::seconds(1)) return;
  if (drawn_ && done < total_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(kWidth * std::clamp(done, 0L, total_) / total_);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kWidth, '.');
  std::fprintf(stderr, "\r%s [%s] %ld/%ld %-40.40s", label_.c_str(), bar.c_str(), done, total_,
               item.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace penumbra
