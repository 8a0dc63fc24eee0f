#pragma once
// Outputs under construction (a temporary file before its rename, a
// temporary folder before it is moved into place) are removed when SIGINT
// or SIGTERM ends the program, so that an interrupted run leaves nothing
// behind. SIGKILL cannot be caught: what it leaves is a hidden ".NAME.tmpPID".
#include <string>

namespace penumbra {

// Installs the SIGINT and SIGTERM handlers: they remove the registered
// paths, then end the program by the same signal (so the parent sees it).
// A crash (SIGABRT from a failed assert in a library, SIGSEGV, SIGBUS,
// SIGFPE, SIGILL) removes them too, says "penumbra: error: internal error
// (signal N: name), please report it" on stderr, and ends the program by
// that signal.
void install_signal_cleanup();

// Registers `path` (a file, or a folder of files) for removal while this
// object lives. At most a few are registered at once; more are not
// registered (and are then left by a signal, not otherwise).
class RemoveOnSignal {
 public:
  RemoveOnSignal(const std::string& path, bool folder);
  ~RemoveOnSignal();
  RemoveOnSignal(const RemoveOnSignal&) = delete;
  RemoveOnSignal& operator=(const RemoveOnSignal&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace penumbra
