#include "io/signal_cleanup.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <climits>
#include <cstring>

namespace penumbra {

namespace {

// A fixed table, so that the handler reads it without allocating or
// locking (only async-signal-safe calls in the handler).
struct Slot {
  std::atomic<bool> used{false};
  std::atomic<bool> ready{false};
  bool folder = false;
  char path[PATH_MAX] = {};
};
constexpr int kSlots = 8;
Slot slots[kSlots];
// Read once at start: whether a crash may come from an address-space limit.
bool address_space_limited = false;

// Removes what a folder holds, subfolders (the report's foliage/ scene)
// to a few levels included, then the folder itself: openat, getdents64,
// unlinkat are all system calls, so this is safe in a signal handler.
constexpr int kMaxFolderDepth = 4;

void remove_folder_contents(int dir, int depth) {
  alignas(8) char buffer[2048];
  for (;;) {
    const long n = ::syscall(SYS_getdents64, dir, buffer, sizeof buffer);
    if (n <= 0) break;
    for (long offset = 0; offset < n;) {
      // struct linux_dirent64: d_ino (8), d_off (8), d_reclen (2), d_type (1), d_name.
      unsigned short length = 0;
      std::memcpy(&length, buffer + offset + 16, sizeof length);
      const unsigned char type = static_cast<unsigned char>(buffer[offset + 18]);
      const char* name = buffer + offset + 19;
      if (std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0) {
        if (type == DT_DIR && depth < kMaxFolderDepth) {
          const int sub = ::openat(dir, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
          if (sub >= 0) {
            remove_folder_contents(sub, depth + 1);
            ::close(sub);
          }
          ::unlinkat(dir, name, AT_REMOVEDIR);
        } else {
          ::unlinkat(dir, name, 0);
        }
      }
      offset += length;
    }
  }
}

// Other threads run on while the handler does (the report's PNG writer
// may put one more file into the folder after its contents are removed,
// and rmdir then fails on it): the folder is emptied again until rmdir
// takes it, a few times at most. Once it is gone, a file can no longer be
// made in it.
constexpr int kFolderRemovalAttempts = 64;

void remove_folder(const char* path) {
  for (int attempt = 0; attempt < kFolderRemovalAttempts; ++attempt) {
    const int dir = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir < 0) return;  // gone (or never made)
    remove_folder_contents(dir, 0);
    ::close(dir);
    if (::rmdir(path) == 0) return;
  }
}

void remove_registered() {
  for (Slot& slot : slots) {
    if (!slot.ready.load()) continue;
    if (slot.folder) {
      remove_folder(slot.path);
    } else {
      ::unlink(slot.path);
    }
  }
}

void on_signal(int signal) {
  remove_registered();
  // End by the same signal, as if it had not been caught.
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

void write_text(const char* text) {
  ssize_t ignored = ::write(2, text, std::strlen(text));
  (void)ignored;
}

// The decimal digits of a small non-negative number, for the handler
// (snprintf is not async-signal-safe).
void write_number(int value) {
  char text[12];
  char* first = text + sizeof text - 1;  // written backwards from the end
  *first = '\0';
  do {
    *--first = static_cast<char>('0' + value % 10);
    value /= 10;
  } while (value > 0 && first > text);
  write_text(first);
}

// A crash (a failed assert in a library, or a driver under memory
// pressure: Mesa dereferences a failed allocation) still leaves no
// temporary output, and says what happened in one line; the signal then
// ends the program as it would have (the exit status tells the truth, and
// a core is dumped where enabled).
void on_crash(int signal) {
  remove_registered();
  write_text("penumbra: error: internal error (signal ");
  write_number(signal);
  write_text(": ");
  write_text(sigdescr_np(signal) != nullptr ? sigdescr_np(signal) : "unknown");
  // Mesa's shader compiler, for one, crashes where an allocation fails.
  write_text(address_space_limited
                 ? "; the address space is limited (ulimit -v): too little for the GPU driver?), "
                   "please report it\n"
                 : "), please report it\n");
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

}  // namespace

void install_signal_cleanup() {
  struct sigaction action {};
  action.sa_handler = &on_signal;
  sigemptyset(&action.sa_mask);
  // Block the other one while handling, so the table is walked once.
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);

  rlimit limit{};
  address_space_limited = getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY;
  struct sigaction crash {};
  crash.sa_handler = &on_crash;
  sigemptyset(&crash.sa_mask);
  crash.sa_flags = SA_RESETHAND | SA_NODEFER;
  for (const int signal : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) {
    sigaction(signal, &crash, nullptr);
  }
}

RemoveOnSignal::RemoveOnSignal(const std::string& path, bool folder) {
  if (path.size() >= PATH_MAX) return;
  for (int i = 0; i < kSlots; ++i) {
    bool expected = false;
    if (!slots[i].used.compare_exchange_strong(expected, true)) continue;
    slots[i].folder = folder;
    std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
    slots[i].ready.store(true);
    slot_ = i;
    return;
  }
}

RemoveOnSignal::~RemoveOnSignal() {
  if (slot_ < 0) return;
  slots[slot_].ready.store(false);
  slots[slot_].used.store(false);
}

}  // namespace penumbra
