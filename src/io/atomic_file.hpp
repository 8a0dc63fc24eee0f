#pragma once
// Whole files written atomically: to a temporary name beside the target,
// then renamed, so a reader (or a crash) never sees half a file.
#include <string>
#include <string_view>

namespace penumbra {

// A temporary name beside `path`, unique to this process: ".NAME.tmpPID".
std::string temporary_name(const std::string& path);

// Renames `temporary` to `path`; on failure removes `temporary` and throws
// RuntimeError naming `path`.
void commit_temporary(const std::string& temporary, const std::string& path);

// Writes `bytes` to `path` atomically. Throws RuntimeError.
void write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace penumbra
