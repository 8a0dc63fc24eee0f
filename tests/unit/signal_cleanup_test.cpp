// The cleanup that SIGINT/SIGTERM run (io/signal_cleanup.hpp) removes a
// registered folder whole, with the subfolders a command writes into it
// (the report's foliage/ scene), so that an interrupted run leaves nothing.
#include "io/signal_cleanup.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

void write_file(const fs::path& path) {
  std::ofstream(path) << "staged";
}

TEST(SignalCleanup, TerminationRemovesARegisteredFolderWithItsSubfolders) {
  const fs::path folder =
      fs::temp_directory_path() / ("penumbra_signal_cleanup_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder / "foliage" / "textures");
  write_file(folder / "index.html");
  write_file(folder / "foliage" / "foliage.gltf");
  write_file(folder / "foliage" / "textures" / "leaf.png");

  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    penumbra::install_signal_cleanup();
    const penumbra::RemoveOnSignal staged(folder.string(), /*folder=*/true);
    ::raise(SIGTERM);
    ::_exit(0);  // not reached: the handler ends the process by SIGTERM
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_FALSE(fs::exists(folder)) << "left behind: " << folder;
  fs::remove_all(folder);
}

}  // namespace
