#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/display_name.hpp"
#include "io/signal_cleanup.hpp"
#include "penumbra/error.hpp"

namespace penumbra {

namespace fs = std::filesystem;

namespace {

// The longest file name Linux file systems take (NAME_MAX).
constexpr std::size_t kNameMax = 255;

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw RuntimeError("cannot write " + display_name(path) + ": " + why);
}

[[noreturn]] void fail_errno(const std::string& path, int error) {
  fail(path, std::strerror(error));
}

// Writes everything to `fd`, retrying short writes; returns 0 or errno.
int write_all(int fd, std::string_view bytes) {
  const char* data = bytes.data();
  std::size_t size = bytes.size();
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    if (n == 0) return EIO;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return 0;
}

// 64-bit FNV-1a of a name, to keep shortened temporary names distinct.
std::uint64_t name_hash(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ull;
  }
  return h;
}

// Writes into an existing file that cannot be replaced (a device, a FIFO):
// opened for writing as it is.
void write_in_place(const std::string& path, std::string_view bytes) {
  // O_APPEND: a redirected regular file behind /dev/fd/N keeps what was
  // written to it before.
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) fail_errno(path, errno);
  const int error = write_all(fd, bytes);
  const int close_error = ::close(fd) != 0 ? errno : 0;
  if (error != 0) fail_errno(path, error);
  if (close_error != 0) fail_errno(path, close_error);
}

// Writes a temporary file beside `path` and renames it over `path`.
// `shown` names the output in messages (the path as given, which may be a
// link to `path`).
void write_and_rename(const std::string& path, std::string_view bytes, const std::string& shown) {
  const std::string temporary = temporary_name(path);
  RemoveOnSignal guard(temporary, false);
  // O_EXCL: never write through something already at the temporary name.
  int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0 && errno == EEXIST) {
    // Left by a killed run of the same process id; it is ours to replace.
    ::unlink(temporary.c_str());
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  }
  if (fd < 0) fail_errno(shown, errno);
  int error = write_all(fd, bytes);
  // fsync before the rename: after a crash the name holds the old file or
  // the whole new one.
  if (error == 0 && ::fsync(fd) != 0 && errno != EINVAL) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && ::rename(temporary.c_str(), path.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(temporary.c_str());
    if (error == EISDIR) fail(shown, "it is a folder");
    fail_errno(shown, error);
  }
}

}  // namespace

std::string temporary_name(const std::string& path) {
  const fs::path p(path);
  std::string stem = p.filename().string();
  const std::string suffix = ".tmp" + std::to_string(getpid());
  if (1 + stem.size() + suffix.size() > kNameMax) {
    char hash[24];
    std::snprintf(hash, sizeof hash, "~%016llx", static_cast<unsigned long long>(name_hash(stem)));
    stem.resize(kNameMax - 1 - suffix.size() - std::strlen(hash));
    stem += hash;
  }
  return (p.parent_path() / ("." + stem + suffix)).string();
}

void write_standard_output(std::string_view bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size()) {
    const int error = errno;
    throw RuntimeError(std::string("cannot write to standard output: ") + std::strerror(error));
  }
  flush_standard_output();
}

void flush_standard_output() {
  if (std::fflush(stdout) != 0) {
    const int error = errno;
    throw RuntimeError(std::string("cannot write to standard output: ") + std::strerror(error));
  }
}

void write_file_atomically(const std::string& path, std::string_view bytes,
                           ExistingOutput existing) {
  if (existing == ExistingOutput::Replace) {
    write_and_rename(path, bytes, path);
    return;
  }
  if (path == "-" || path == "/dev/stdout") {
    write_standard_output(bytes);
    return;
  }
  // /dev/stderr, /dev/fd/N, /proc/self/fd/N: links to an open file, which
  // may be regular (a redirection); written in place, never replaced.
  if (path.rfind("/dev/", 0) == 0 || path.rfind("/proc/", 0) == 0) {
    write_in_place(path, bytes);
    return;
  }
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno != ENOENT) fail_errno(path, errno);
    struct stat link {};
    if (::lstat(path.c_str(), &link) == 0) fail(path, "it is a link to nothing");
    write_and_rename(path, bytes, path);
    return;
  }
  if (S_ISDIR(st.st_mode)) fail(path, "it is a folder");
  if (!S_ISREG(st.st_mode)) {
    write_in_place(path, bytes);
    return;
  }
  struct stat link {};
  if (::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
    // Replace the file the link points to, not the link.
    std::error_code ec;
    const fs::path target = fs::canonical(path, ec);
    if (ec) fail(path, ec.message());
    write_and_rename(target.string(), bytes, path);
    return;
  }
  write_and_rename(path, bytes, path);
}

}  // namespace penumbra
