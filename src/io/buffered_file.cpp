#include "io/buffered_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <new>

#include "penumbra/error.hpp"

namespace penumbra {

BufferedFile::BufferedFile(const std::string& path, std::size_t buffer_bytes)
    : path_(path), capacity_(buffer_bytes) {
  // O_NONBLOCK: a FIFO opens at once instead of waiting for a writer (and
  // is then refused below).
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd_ < 0) throw RuntimeError(path + ": cannot be opened (" + std::strerror(errno) + ")");
  struct stat status {};
  if (::fstat(fd_, &status) != 0 || !S_ISREG(status.st_mode)) {
    ::close(fd_);
    throw RuntimeError(path + ": is not a regular file");
  }
  file_left_ = static_cast<std::size_t>(status.st_size);
  // malloc, not new char[]: the buffer is not zeroed, and its pages are
  // touched only as far as the file fills them.
  buffer_ = static_cast<char*>(std::malloc(capacity_));
  if (buffer_ == nullptr) {
    ::close(fd_);
    throw std::bad_alloc();
  }
}

BufferedFile::~BufferedFile() {
  std::free(buffer_);
  if (fd_ >= 0) ::close(fd_);
}

void BufferedFile::fill(std::size_t size) {
  if (begin_ > 0) {
    std::memmove(buffer_, buffer_ + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  while (end_ < size && file_left_ > 0) {
    const ssize_t n = ::read(fd_, buffer_ + end_, std::min(capacity_ - end_, file_left_));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw RuntimeError(path_ + ": cannot be read (" + std::strerror(errno) + ")");
    if (n == 0) {  // the file shrank while read
      file_left_ = 0;
      break;
    }
    end_ += static_cast<std::size_t>(n);
    file_left_ -= static_cast<std::size_t>(n);
  }
}

const char* BufferedFile::take(std::size_t size) {
  if (size > capacity_) throw RuntimeError(path_ + ": a record is larger than the read buffer");
  if (end_ - begin_ < size) fill(size);
  if (end_ - begin_ < size) return nullptr;
  const char* p = buffer_ + begin_;
  begin_ += size;
  return p;
}

std::string_view BufferedFile::lines() {
  fill(capacity_);
  if (begin_ == end_) return {};
  const char* first = buffer_ + begin_;
  std::size_t size = end_ - begin_;
  if (file_left_ > 0) {
    const void* last = ::memrchr(first, '\n', size);
    if (last == nullptr)
      throw RuntimeError(path_ + ": a line is longer than " + std::to_string(capacity_ >> 20) +
                         " MiB");
    size = static_cast<std::size_t>(static_cast<const char*>(last) - first) + 1;
  }
  begin_ += size;
  return {first, size};
}

}  // namespace penumbra
