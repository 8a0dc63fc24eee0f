#include "cli/cli_run.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace penumbra::testing {

namespace fs = std::filesystem;

Result run(const std::string& args) {
  const fs::path dir = fs::path(PENUMBRA_TEST_OUTPUT) / "cli";
  fs::create_directories(dir);
  // One file per process: CTest runs tests in parallel.
  const std::string err_file = (dir / ("stderr-" + std::to_string(getpid()) + ".txt")).string();
  const std::string cmd = std::string(PENUMBRA_BINARY) + " " + args + " 2>" + err_file;
  Result r;
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), pipe)) r.out += buf.data();
  int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  {
    std::ifstream in(err_file);
    r.err.assign(std::istreambuf_iterator<char>(in), {});
  }
  fs::remove(err_file);
  return r;
}

std::string out_path(const std::string& name) {
  fs::path dir = fs::path(PENUMBRA_TEST_OUTPUT) / "cli";
  fs::create_directories(dir);
  fs::path p = dir / name;
  fs::remove_all(p);
  return p.string();
}

bool is_one_error_line(const std::string& text, const std::string& culprit) {
  return text.rfind("penumbra: error: ", 0) == 0 &&
         std::count(text.begin(), text.end(), '\n') == 1 && text.find(culprit) != std::string::npos;
}

void expect_error(const std::string& args, int status, const std::string& culprit,
                  const std::string& output, const std::string& output_flag) {
  Result r = run(args + " " + output_flag + " " + output);
  EXPECT_EQ(r.status, status) << args << "\n" << r.err;
  EXPECT_EQ(r.err.rfind("penumbra: error: ", 0), 0u) << args << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line expected:\n" << r.err;
  EXPECT_NE(r.err.find(culprit), std::string::npos) << args << "\nmessage: " << r.err;
  EXPECT_FALSE(fs::exists(output)) << "output left behind for: " << args;
  // No temporary files either: those of this output's name (other tests
  // running beside this one may be writing theirs).
  const fs::path folder = fs::path(output).parent_path();
  if (!fs::is_directory(folder)) return;
  const std::string temporary_prefix = "." + fs::path(output).filename().string() + ".tmp";
  for (const auto& entry : fs::directory_iterator(folder)) {
    EXPECT_NE(entry.path().filename().string().rfind(temporary_prefix, 0), 0u)
        << entry.path() << " left behind by: " << args;
  }
}

}  // namespace penumbra::testing
