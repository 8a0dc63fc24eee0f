#pragma once
// A folder of outputs (`compare -o DIR`, `report -o DIR`) built where
// nobody sees it half done: in a temporary sibling ".DIR.tmpPID" (or, when
// DIR exists, in "DIR/.staged.tmpPID"), moved into place only when
// complete. On failure (an exception, or SIGINT or SIGTERM) the temporary
// folder is removed and DIR is as it was.
#include <memory>
#include <string>

#include "io/signal_cleanup.hpp"

namespace penumbra {

class StagedFolder {
 public:
  // Creates the temporary folder beside `final_dir`. Throws RuntimeError.
  explicit StagedFolder(std::string final_dir);
  // Removes the temporary folder unless publish() succeeded.
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  // Where the files go while the folder is built.
  [[nodiscard]] const std::string& path() const { return staging_; }
  // `name` inside the final folder (what messages and pages refer to).
  [[nodiscard]] std::string final_path(const std::string& name) const;

  // Moves the outputs into place: the whole folder by one rename when
  // DIR does not exist, else each file into DIR (replacing files of the
  // same name, keeping the others). Throws RuntimeError.
  void publish();

 private:
  std::string final_;
  std::string staging_;
  std::unique_ptr<RemoveOnSignal> guard_;
  bool published_ = false;
};

}  // namespace penumbra
