#pragma once
// Running the real `penumbra` binary from tests, and checking the way it
// fails: one "penumbra: error:" line naming the culprit, the documented
// exit status, no output left behind.
#include <string>

namespace penumbra::testing {

struct Result {
  int status = -1;
  std::string err;
  std::string out;
};

// Runs `penumbra ARGS`, capturing stdout and stderr.
Result run(const std::string& args);

// A path under the tests' output folder, removed if it exists.
std::string out_path(const std::string& name);

// True if `text` has exactly one line, starting "penumbra: error: " and
// containing `culprit`.
bool is_one_error_line(const std::string& text, const std::string& culprit);

// Runs `ARGS OUTPUT_FLAG OUTPUT` and expects the status, one error line
// naming the culprit, and neither OUTPUT nor a temporary file of its name
// beside it afterwards.
void expect_error(const std::string& args, int status, const std::string& culprit,
                  const std::string& output, const std::string& output_flag = "-o");

}  // namespace penumbra::testing
