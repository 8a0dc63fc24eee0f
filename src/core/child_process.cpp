#include "core/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>
#include <system_error>

namespace penumbra {

namespace {

// The child's answer: one tag byte, then the work's bytes or its message.
constexpr char kAnswer = 'A';
constexpr char kThrew = 'T';
constexpr char kOutOfMemory = 'M';

bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

// The child's own limits, set before the work starts: it dies with the
// parent (whatever kills the parent, even SIGKILL), it sits in its own
// process group (so the parent can end it and anything it started as one),
// and its address space is capped.
void confine_child(pid_t parent, std::size_t memory_limit) {
  ::setpgid(0, 0);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  // The parent may have died before prctl: then nobody waits for the answer.
  if (::getppid() != parent) _exit(1);
  // The parent's handlers (its clean-up of outputs on SIGINT and SIGTERM,
  // its one-line report of a crash) are not the child's: a crash here is
  // the parent's to report.
  for (const int signal : {SIGINT, SIGTERM, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) {
    ::signal(signal, SIG_DFL);
  }
  if (memory_limit > 0) {
    const rlimit limit{memory_limit, memory_limit};
    ::setrlimit(RLIMIT_AS, &limit);
  }
}

[[noreturn]] void run_child(int fd, const std::function<std::string()>& work) {
  std::string message;
  try {
    message = kAnswer + work();
  } catch (const std::bad_alloc&) {
    message = kOutOfMemory;
  } catch (const std::exception& e) {
    message = kThrew + std::string(e.what());
  } catch (...) {
    message = kThrew + std::string("unknown exception");
  }
  _exit(write_all(fd, message.data(), message.size()) ? 0 : 1);
}

std::system_error system_error(const char* what) {
  return std::system_error(errno, std::generic_category(), what);
}

// Waits for the child, retrying when a signal interrupts.
int wait_for(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw system_error("waitpid");
  }
  return status;
}

// Ends the child's process group (the child and anything it started) and
// reaps the child.
int end_child(pid_t pid, bool kill_first) {
  if (kill_first) ::kill(-pid, SIGKILL);
  const int status = wait_for(pid);
  ::kill(-pid, SIGKILL);  // what the child may have left running
  return status;
}

}  // namespace

std::string run_in_child_process(const std::function<std::string()>& work,
                                 const ChildLimits& limits) {
  const pid_t parent = ::getpid();
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw system_error("pipe2");
  const pid_t pid = fork();
  if (pid < 0) {
    const auto error = system_error("fork");
    close(fds[0]);
    close(fds[1]);
    throw error;
  }
  if (pid == 0) {
    close(fds[0]);
    confine_child(parent, limits.memory_bytes);
    run_child(fds[1], work);
  }
  // Also here, so the group exists whichever process runs first.
  ::setpgid(pid, pid);
  close(fds[1]);

  // Read the answer until the child closes its end (it exits), or the
  // time runs out.
  const std::chrono::milliseconds time_limit = limits.time;
  const auto deadline = std::chrono::steady_clock::now() + time_limit;
  std::string answer;
  char buffer[1 << 16];
  bool timed_out = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{.fd = fds[0], .events = POLLIN, .revents = 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1 << 30)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) {
      const auto error = system_error("poll");
      end_child(pid, true);
      close(fds[0]);
      throw error;
    }
    if (ready == 0) continue;  // the deadline is checked above
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of file (or an error): the child is done
    answer.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  const int status = end_child(pid, timed_out);

  if (timed_out) {
    std::ostringstream limit;
    limit << static_cast<double>(time_limit.count()) / 1000.0;
    throw ChildProcessError(ChildProcessError::Kind::TimedOut,
                            "did not finish within " + limit.str() + " s");
  }
  if (answer.size() == 1 && answer.front() == kOutOfMemory) {
    throw ChildProcessError(
        ChildProcessError::Kind::OutOfMemory,
        "ran out of memory (its limit is " + std::to_string(limits.memory_bytes >> 20) + " MiB)");
  }
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    throw ChildProcessError(
        ChildProcessError::Kind::Crashed,
        "crashed (signal " + std::to_string(signal) + ": " + std::string(strsignal(signal)) + ")");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || answer.empty()) {
    throw ChildProcessError(ChildProcessError::Kind::Crashed, "ended without an answer");
  }
  if (answer.front() == kThrew) {
    throw ChildProcessError(ChildProcessError::Kind::Threw, answer.substr(1));
  }
  answer.erase(0, 1);
  return answer;
}

std::string run_in_child_process(const std::function<std::string()>& work,
                                 std::chrono::milliseconds time_limit) {
  return run_in_child_process(work, ChildLimits{.time = time_limit, .memory_bytes = 0});
}

}  // namespace penumbra
