#include "io/progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace penumbra {

namespace {

constexpr auto kDelay = std::chrono::seconds(1);
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
constexpr int kBarWidth = 30;

}  // namespace

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)), start_(Clock::now()), terminal_(isatty(STDERR_FILENO) == 1) {}

ProgressBar::~ProgressBar() {
  finish();
}

void ProgressBar::update(std::int64_t done, std::int64_t total) {
  if (!terminal_ || total <= 0) return;
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  const Clock::time_point now = Clock::now();
  if (now - start_ < kDelay || (drawn_ && now - last_draw_ < kRedrawInterval)) return;
  draw(done, total, now);
}

void ProgressBar::step(const std::string& name, std::int64_t done, std::int64_t total) {
  std::lock_guard lock(mutex_);
  step_ = name;
  const Clock::time_point now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (terminal_) {
    if (drawn_) draw(done, total, now);
    return;
  }
  // The process's CPU time (all threads) as well: where the work went.
  const double cpu = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
  std::fprintf(stderr, "%s: %s (%lld of %lld items done, %.1f s, %.1f s CPU)\n", label_.c_str(),
               name.c_str(), static_cast<long long>(done), static_cast<long long>(total), elapsed,
               cpu);
  std::fflush(stderr);
}

void ProgressBar::draw(std::int64_t done, std::int64_t total, Clock::time_point now) {
  last_draw_ = now;
  drawn_ = true;
  const double fraction =
      std::clamp(static_cast<double>(done) / static_cast<double>(total), 0.0, 1.0);
  const int filled = static_cast<int>(fraction * kBarWidth);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.append(static_cast<std::size_t>(kBarWidth - filled), '.');
  std::string line = label_;
  if (!step_.empty()) line += ": " + step_;
  char numbers[96];
  if (step_.empty()) {
    std::snprintf(numbers, sizeof numbers, " [%s] %3d%%  %.0f s", bar.c_str(),
                  static_cast<int>(fraction * 100.0), elapsed);
  } else if (done > 0) {
    // What is left at the pace so far.
    const double left = elapsed * static_cast<double>(total - done) / static_cast<double>(done);
    std::snprintf(numbers, sizeof numbers, " [%s] %lld/%lld  %.0f s, about %.0f s left",
                  bar.c_str(), static_cast<long long>(done), static_cast<long long>(total), elapsed,
                  std::max(0.0, left));
  } else {
    std::snprintf(numbers, sizeof numbers, " [%s] %lld/%lld  %.0f s", bar.c_str(),
                  static_cast<long long>(done), static_cast<long long>(total), elapsed);
  }
  line += numbers;
  // Pad over a longer line drawn before.
  const std::size_t width = line.size();
  if (width < drawn_width_) line.append(drawn_width_ - width, ' ');
  drawn_width_ = std::max(drawn_width_, width);
  std::fprintf(stderr, "\r%s", line.c_str());
  std::fflush(stderr);
}

void ProgressBar::finish() {
  std::lock_guard lock(mutex_);
  if (!drawn_) return;
  // Erase the line: spaces over it, back to its start.
  std::fprintf(stderr, "\r%*s\r", static_cast<int>(drawn_width_), "");
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace penumbra
