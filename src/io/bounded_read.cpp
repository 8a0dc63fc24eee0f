#include "io/bounded_read.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/display_name.hpp"
#include "penumbra/error.hpp"

namespace penumbra {

namespace {

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  [[nodiscard]] int get() const { return fd_; }

 private:
  int fd_;
};

std::string megabytes(std::size_t bytes) {
  return std::to_string(bytes >> 20) + " MiB";
}

}  // namespace

std::string read_bounded_file(const std::string& path, std::size_t max_bytes,
                              const std::string& what) {
  auto fail = [&](const std::string& why) -> std::string {
    throw RuntimeError(what + " " + display_name(path) + ": " + why);
  };
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a
  // writer; it is refused below before any read.
  const Fd fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
  if (fd.get() < 0) {
    if (errno == ENOENT) return fail("no such file");
    return fail(std::strerror(errno));
  }
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) return fail(std::strerror(errno));
  if (S_ISDIR(st.st_mode)) return fail("is a folder, not a file");
  if (!S_ISREG(st.st_mode)) return fail("is not a regular file (a device, FIFO or socket)");
  if (static_cast<unsigned long long>(st.st_size) > max_bytes) {
    return fail("is larger than the limit of " + megabytes(max_bytes));
  }
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(st.st_size));
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return fail(std::strerror(errno));
    if (n == 0) break;
    // The file may grow while it is read: the limit holds all the same.
    if (bytes.size() + static_cast<std::size_t>(n) > max_bytes) {
      return fail("is larger than the limit of " + megabytes(max_bytes));
    }
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  return bytes;
}

}  // namespace penumbra
