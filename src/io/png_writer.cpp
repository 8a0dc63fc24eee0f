#include "io/png_writer.hpp"

#include <exception>
#include <utility>

#include "penumbra/error.hpp"

namespace penumbra {

BackgroundPngWriter::BackgroundPngWriter() : thread_([this] { run(); }) {}

BackgroundPngWriter::~BackgroundPngWriter() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void BackgroundPngWriter::write(const Image& image, const std::string& path, PngEncoding encoding) {
  Job job{path, png_pixels(image, encoding)};
  const std::size_t bytes = job.pixels.rgb.size();
  std::unique_lock lock(mutex_);
  // One file larger than the bound still goes, alone.
  changed_.wait(lock, [&] { return queue_.empty() || queued_bytes_ + bytes <= kMaxQueuedBytes; });
  queued_bytes_ += bytes;
  queue_.push_back(std::move(job));
  lock.unlock();
  changed_.notify_all();
}

void BackgroundPngWriter::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return queue_.empty() && !writing_; });
  if (!failure_.empty()) throw RuntimeError(std::exchange(failure_, {}));
}

void BackgroundPngWriter::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return !queue_.empty() || closing_; });
    if (queue_.empty()) return;  // closing, and every file written
    Job job = std::move(queue_.front());
    queue_.pop_front();
    writing_ = true;
    lock.unlock();
    std::string failure;
    try {
      write_png(job.pixels, job.path);
    } catch (const std::exception& e) {
      failure = e.what();
    }
    lock.lock();
    writing_ = false;
    queued_bytes_ -= job.pixels.rgb.size();
    if (failure_.empty()) failure_ = std::move(failure);
    changed_.notify_all();
  }
}

}  // namespace penumbra
