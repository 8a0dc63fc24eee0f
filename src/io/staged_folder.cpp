#include "io/staged_folder.hpp"

#include <filesystem>
#include <system_error>

#include "core/display_name.hpp"
#include "io/atomic_file.hpp"
#include "penumbra/error.hpp"

namespace penumbra {

namespace fs = std::filesystem;

namespace {

// "DIR/" and "DIR" name the same folder; the temporary sibling needs the
// name without the slash.
fs::path without_trailing_slash(const std::string& dir) {
  fs::path p = fs::path(dir).lexically_normal();
  if (p.has_filename()) return p;
  return p.parent_path();
}

}  // namespace

StagedFolder::StagedFolder(std::string final_dir) : final_(std::move(final_dir)) {
  std::error_code ec;
  // Inside an existing folder (the same file system as the files it will
  // hold, even where DIR is a link to another disk), else beside it.
  staging_ = fs::is_directory(final_, ec) ? temporary_name((fs::path(final_) / "staged").string())
                                          : temporary_name(without_trailing_slash(final_).string());
  fs::remove_all(staging_, ec);  // left by a killed run of the same process id
  guard_ = std::make_unique<RemoveOnSignal>(staging_, true);
  if (!fs::create_directory(staging_, ec) || ec) {
    throw RuntimeError("cannot create folder " + display_name(staging_) + ": " +
                       (ec ? ec.message() : std::string("it exists")));
  }
}

StagedFolder::~StagedFolder() {
  if (published_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

std::string StagedFolder::final_path(const std::string& name) const {
  return (fs::path(final_) / name).string();
}

void StagedFolder::publish() {
  std::error_code ec;
  const fs::path target = without_trailing_slash(final_);
  if (!fs::exists(target, ec)) {
    fs::rename(staging_, target, ec);
    if (ec) {
      throw RuntimeError("cannot create folder " + display_name(final_) + ": " + ec.message());
    }
  } else {
    for (const fs::directory_entry& entry : fs::directory_iterator(staging_)) {
      fs::rename(entry.path(), target / entry.path().filename(), ec);
      if (ec) {
        throw RuntimeError("cannot write " +
                           display_name((target / entry.path().filename()).string()) + ": " +
                           ec.message());
      }
    }
    fs::remove(staging_, ec);
  }
  published_ = true;
}

}  // namespace penumbra
