#pragma once
// Running work that may crash or never return (a third-party file reader
// fed a malformed file) in a child process, so that the program survives
// both and can say what happened.
#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>

namespace penumbra {

class ChildProcessError : public std::runtime_error {
 public:
  enum class Kind {
    Threw,        // the work threw: what() is its message
    Crashed,      // the child died (a signal, or it exited without an answer)
    TimedOut,     // it ran past the time limit and was killed
    OutOfMemory,  // an allocation failed under the memory limit
  };
  ChildProcessError(Kind kind, const std::string& what) : std::runtime_error(what), kind_(kind) {}
  [[nodiscard]] Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

struct ChildLimits {
  std::chrono::milliseconds time{10'000};
  // The child's address space (RLIMIT_AS), in bytes; 0: no limit.
  std::size_t memory_bytes = 0;
};

// Forks, runs `work` in the child and returns the bytes it returned,
// passed back through a pipe. The child ends with _exit, so it flushes no
// stdio buffers and runs no exit handlers of the parent's. Throws
// ChildProcessError when the work throws, the child crashes, runs out of
// memory, or takes longer than the time limit (the child is then killed).
// The child dies with this process (PR_SET_PDEATHSIG), runs in its own
// process group, which is killed when it is done, and under the memory
// limit. Call it before
// starting threads of one's own: a forked child has only the calling
// thread, and locks other threads held stay held.
std::string run_in_child_process(const std::function<std::string()>& work,
                                 const ChildLimits& limits);

// The same with a time limit alone.
std::string run_in_child_process(const std::function<std::string()>& work,
                                 std::chrono::milliseconds time_limit);

}  // namespace penumbra
