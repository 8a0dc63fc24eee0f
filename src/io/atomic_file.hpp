#pragma once
// Files written atomically: to a temporary name beside the target, then
// renamed over it, so a failure never leaves a partial file behind.
#include <string>

namespace penumbra {

// A temporary name in the target's folder, unique to this process.
std::string temporary_path_for(const std::string& path);

// Renames the temporary file to `path`; on failure removes it and throws
// RuntimeError naming `path`.
void commit_temporary(const std::string& temporary, const std::string& path);

// Writes `text` to `path` atomically. Throws RuntimeError.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace penumbra
