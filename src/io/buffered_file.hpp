#pragma once
// Reading a large file front to back through one fixed buffer, so that a
// reader parses a file of any size in a few MiB of memory (no copy of the
// whole file, no huge zeroed temporary).
#include <cstddef>
#include <string>
#include <string_view>

namespace penumbra {

class BufferedFile {
 public:
  // Opens a regular file for reading. Throws RuntimeError "<path>: <why>".
  explicit BufferedFile(const std::string& path, std::size_t buffer_bytes = std::size_t{4} << 20);
  ~BufferedFile();
  BufferedFile(const BufferedFile&) = delete;
  BufferedFile& operator=(const BufferedFile&) = delete;

  // The next `size` bytes (at most the buffer's size), or null if the file
  // ends first. The pointer is valid until the next call.
  const char* take(std::size_t size);

  // The next whole lines: the buffered bytes up to and including the last
  // line feed (or, at the end of the file, whatever is left). Empty once
  // the file is read. A line longer than the buffer is an error.
  std::string_view lines();

  // Bytes of the file not yet taken (its size when opened, less those taken).
  [[nodiscard]] std::size_t left() const { return file_left_ + (end_ - begin_); }

 private:
  // Moves the unread bytes to the front and reads until `size` bytes are
  // buffered or the file ends.
  void fill(std::size_t size);

  std::string path_;
  int fd_ = -1;
  char* buffer_ = nullptr;
  std::size_t capacity_ = 0;
  std::size_t begin_ = 0, end_ = 0;  // unread bytes: buffer_[begin_, end_)
  std::size_t file_left_ = 0;        // bytes of the file not yet buffered
};

}  // namespace penumbra
