// Work run in a child process: its answer comes back whole, and its
// exceptions, crashes and endless loops become errors of the caller's.
#include "core/child_process.hpp"

#include <gtest/gtest.h>
#include <signal.h>

#include <string>

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

}  // namespace
}  // namespace penumbra
