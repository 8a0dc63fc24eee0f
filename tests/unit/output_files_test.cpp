// Files read and written by the program whatever the path names: reads
// bounded to regular files, temporary names within the name limit, links
// and devices written through, names escaped in messages.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "core/display_name.hpp"
#include "io/atomic_file.hpp"
#include "io/bounded_read.hpp"
#include "penumbra/error.hpp"
#include "scene/scene_checks.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(PENUMBRA_TEST_OUTPUT) / "output_files" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string error_of(const std::function<void()>& work) {
  try {
    work();
  } catch (const RuntimeError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BoundedRead, ReadsRegularFilesWithinTheLimitOnly) {
  const fs::path dir = fresh_dir("bounded");
  const std::string file = (dir / "a.json").string();
  std::ofstream(file) << "0123456789";
  EXPECT_EQ(read_bounded_file(file, 10, "scene file"), "0123456789");
  EXPECT_EQ(error_of([&] { read_bounded_file(file, 9, "scene file"); }),
            "scene file '" + file + "': is larger than the limit of 0 MiB");
  const std::string fifo = (dir / "fifo").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(error_of([&] { read_bounded_file(fifo, 10, "x"); }).find("not a regular file"),
            std::string::npos);
  EXPECT_NE(error_of([&] { read_bounded_file("/dev/zero", 10, "x"); }).find("not a regular file"),
            std::string::npos);
  EXPECT_NE(error_of([&] { read_bounded_file(dir.string(), 10, "x"); }).find("is a folder"),
            std::string::npos);
}

TEST(AtomicFile, TemporaryNamesStayWithinTheNameLimit) {
  const std::string longest(255, 'n');
  const std::string temporary = fs::path(temporary_name("dir/" + longest)).filename().string();
  EXPECT_LE(temporary.size(), 255u);
  EXPECT_EQ(temporary.front(), '.');
  // Two long names that share their start still get different names.
  EXPECT_NE(temporary_name(longest), temporary_name(std::string(254, 'n') + "m"));
  EXPECT_EQ(fs::path(temporary_name("dir/a.png")).filename().string(),
            ".a.png.tmp" + std::to_string(getpid()));
}

TEST(AtomicFile, LinksAreWrittenThroughAndKept) {
  const fs::path dir = fresh_dir("links");
  const fs::path target = dir / "target.json";
  std::ofstream(target) << "old";
  fs::create_symlink(target, dir / "link.json");
  write_file_atomically((dir / "link.json").string(), "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
  std::ifstream in(target);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "new");
  // A link to nothing is refused rather than replaced.
  fs::create_symlink(dir / "missing", dir / "dangling.json");
  EXPECT_NE(error_of([&] {
              write_file_atomically((dir / "dangling.json").string(), "x");
            }).find("a link to nothing"),
            std::string::npos);
  EXPECT_TRUE(fs::is_symlink(dir / "dangling.json"));
  // A device is written in place.
  write_file_atomically("/dev/null", "discarded");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(DisplayName, ControlCharactersAreEscaped) {
  EXPECT_EQ(display_name("a\nb\x1b[31m\tc"), "'a\\nb\\x1b[31m\\tc'");
  EXPECT_EQ(display_name("plain/path.json"), "'plain/path.json'");
}

TEST(SceneChecks, DegenerateCamerasAndDirections) {
  Camera camera;
  EXPECT_EQ(camera_defect(camera), CameraDefect::None);
  camera.position = {0.0f, 10.0f, 0.0f};
  camera.target = {0.0f, 0.0f, 0.0f};
  EXPECT_EQ(camera_defect(camera), CameraDefect::UpAlongView);
  camera.target = camera.position + glm::vec3(1e-30f, 0.0f, 1e-30f);
  EXPECT_EQ(camera_defect(camera), CameraDefect::TargetAtPosition);
  EXPECT_FALSE(is_usable_direction({0.0f, -1e-25f, 0.0f}));
  EXPECT_TRUE(is_usable_direction({0.0f, -1e-3f, 0.0f}));
}

}  // namespace
}  // namespace penumbra
