#pragma once
// PNG files compressed and written on a thread of their own, so that the
// thread that renders them goes on rendering: compressing a 640x360 frame
// takes about as long as a pass of llvmpipe, and a report writes a few
// hundred.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <string>
#include <thread>

#include "io/image.hpp"

namespace penumbra {

class BackgroundPngWriter {
 public:
  BackgroundPngWriter();
  // Writes what is queued; failures then go unreported (finish() reports
  // them).
  ~BackgroundPngWriter();
  BackgroundPngWriter(const BackgroundPngWriter&) = delete;
  BackgroundPngWriter& operator=(const BackgroundPngWriter&) = delete;

  // Makes `image`'s bytes now (png_pixels: the image may change after)
  // and queues them for `path`, written atomically as write_png writes.
  // Waits while the queue holds more than kMaxQueuedBytes.
  void write(const Image& image, const std::string& path, PngEncoding encoding);
  // Waits until every queued file is written. Throws RuntimeError for the
  // first that could not be (once; the others were still written).
  void finish();

  static constexpr std::size_t kMaxQueuedBytes = std::size_t{128} << 20;

 private:
  struct Job {
    std::string path;
    PngPixels pixels;
  };
  void run();

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> queue_;
  std::size_t queued_bytes_ = 0;
  bool writing_ = false;  // a job taken from the queue, not yet written
  bool closing_ = false;
  std::string failure_;
  std::thread thread_;
};

}  // namespace penumbra
