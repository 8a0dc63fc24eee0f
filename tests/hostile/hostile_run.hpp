#pragma once
// Running the real binary the way a careless or hostile user would: under
// resource limits, with odd files in odd places, killed mid-run.
#include <sys/types.h>

#include <string>
#include <vector>

namespace penumbra::hostile {

struct Result {
  int status = -1;  // the exit status, or 128 + the signal that ended it
  std::string out;
  std::string err;
};

// The binary's path, quoted for the shell.
std::string binary();

// Runs `line` with /bin/sh (so `ulimit`, `timeout` and redirections work),
// capturing stdout and stderr; "PENUMBRA" in `line` (not followed by "_") stands for the binary.
Result shell(const std::string& line);

// A fresh, empty folder for one test.
std::string fresh_dir(const std::string& name);

// Starts the binary with `args`, its stdout on `stdout_fd` and its stderr
// on `stderr_fd` (-1: /dev/null); returns its process id.
pid_t spawn(const std::vector<std::string>& args, int stdout_fd = -1, int stderr_fd = -1);

// The process ids whose parent is `parent`.
std::vector<pid_t> children_of(pid_t parent);

// Whether `pid` is still running (a zombie is not).
bool running(pid_t pid);

// True if `text` is one line "penumbra: error: ..." containing `culprit`.
bool one_error_line(const std::string& text, const std::string& culprit);

// The same for stderr that may start with progress lines (a command off a
// terminal reports its progress there): the error is the one
// "penumbra: error: " line, and the last.
bool ends_in_one_error_line(const std::string& text, const std::string& culprit);

// The lines of `text` that start with `prefix` ("penumbra: warning: ").
long lines_starting_with(const std::string& text, const std::string& prefix);

// Writes `text` to `path`.
void write_text(const std::string& path, const std::string& text);

// The file's contents.
std::string read_text(const std::string& path);

}  // namespace penumbra::hostile
