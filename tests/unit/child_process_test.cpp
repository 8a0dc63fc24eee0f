// Work run in a child process: its answer comes back whole, and its
// exceptions, crashes and endless loops become errors of the caller's.
#include "core/child_process.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace penumbra {
namespace {

using namespace std::chrono_literals;

ChildProcessError failure_of(const std::function<std::string()>& work,
                             std::chrono::milliseconds limit = 10s) {
  try {
    run_in_child_process(work, limit);
  } catch (const ChildProcessError& e) {
    return e;
  }
  ADD_FAILURE() << "the work did not fail";
  return ChildProcessError(ChildProcessError::Kind::Threw, "");
}

TEST(ChildProcess, ReturnsTheAnswerWhole) {
  // Larger than a pipe's buffer, with every byte value.
  std::string expected(5 << 20, '\0');
  for (std::size_t i = 0; i < expected.size(); ++i)
    expected[i] = static_cast<char>(i * 7 + i / 251);
  EXPECT_EQ(run_in_child_process([&] { return expected; }, 60s), expected);
  EXPECT_EQ(run_in_child_process([] { return std::string(); }, 60s), "");
}

TEST(ChildProcess, AnExceptionKeepsItsMessage) {
  const ChildProcessError e = failure_of([]() -> std::string { throw std::runtime_error("bad"); });
  EXPECT_EQ(e.kind(), ChildProcessError::Kind::Threw);
  EXPECT_STREQ(e.what(), "bad");
}

TEST(ChildProcess, ACrashIsAnError) {
  const ChildProcessError e = failure_of([]() -> std::string {
    raise(SIGSEGV);
    return "survived";
  });
  EXPECT_EQ(e.kind(), ChildProcessError::Kind::Crashed);
  EXPECT_NE(std::string(e.what()).find("signal " + std::to_string(SIGSEGV)), std::string::npos)
      << e.what();
}

TEST(ChildProcess, AnEndlessLoopIsStopped) {
  const ChildProcessError e = failure_of(
      []() -> std::string {
        for (volatile bool forever = true; forever;) {
        }
        return "";
      },
      300ms);
  EXPECT_EQ(e.kind(), ChildProcessError::Kind::TimedOut);
  EXPECT_STREQ(e.what(), "did not finish within 0.3 s");
}

TEST(ChildProcess, TheMemoryLimitHolds) {
  // 4 GiB asked for under a 512 MiB limit: an error saying so, at once.
  try {
    run_in_child_process(
        []() -> std::string {
          std::vector<char> block(std::size_t{4} << 30, 'x');
          return std::string(1, block.back());
        },
        ChildLimits{.time = 60s, .memory_bytes = std::size_t{512} << 20});
    ADD_FAILURE() << "the work did not fail";
  } catch (const ChildProcessError& e) {
    EXPECT_EQ(e.kind(), ChildProcessError::Kind::OutOfMemory) << e.what();
    EXPECT_STREQ(e.what(), "ran out of memory (its limit is 512 MiB)");
  }
}

TEST(ChildProcess, WhatTheChildStartsEndsWithIt) {
  // A grandchild left running in the child's process group is killed when
  // the child is done.
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  run_in_child_process(
      [&]() -> std::string {
        if (fork() == 0) {
          // Holds the test pipe's write end open, and nothing else (the
          // answer's pipe would keep the parent reading).
          for (int fd = 3; fd < 1024; ++fd) {
            if (fd != fds[1]) close(fd);
          }
          for (;;) pause();
        }
        return "done";
      },
      60s);
  close(fds[1]);
  // The read ends (end of file) only once every holder of the write end,
  // the grandchild included, is gone.
  char byte = 0;
  EXPECT_EQ(read(fds[0], &byte, 1), 0);
  close(fds[0]);
}

}  // namespace
}  // namespace penumbra
