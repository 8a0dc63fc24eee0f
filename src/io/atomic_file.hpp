#pragma once
// Whole files written atomically: to a temporary name beside the target,
// then renamed, so a reader (or a crash) never sees half a file. Every
// write is checked, through fsync and close: a full disk or a file-size
// limit is an error, never a truncated file published.
//
// What the output path already is decides how it is written:
// - nothing, or a regular file: the atomic write above;
// - a symbolic link: the file it points to is written (atomically, if a
//   regular file), the link itself is kept;
// - a device, FIFO or socket (/dev/null, a named pipe), or any path under
//   /dev or /proc (/dev/fd/2 may be a redirected regular file): written in
//   place, as it cannot be replaced;
// - "-" or /dev/stdout: standard output (through stdio, after what the
//   program printed there).
#include <string>
#include <string_view>

namespace penumbra {

// A temporary name beside `path`, unique to this process:
// ".NAME.tmpPID", with NAME shortened (and a hash of it appended) where the
// whole would exceed the file-name limit (255 bytes).
std::string temporary_name(const std::string& path);

// What to do with an existing output that is not a regular file.
enum class ExistingOutput {
  WriteInPlace,  // a device or FIFO the user named: write into it
  Replace,       // a file of the program's own (a cache entry): replace it
};

// Writes `bytes` to `path` as described above. Throws RuntimeError naming
// the path and the reason (the system's, e.g. "No space left on device").
void write_file_atomically(const std::string& path, std::string_view bytes,
                           ExistingOutput existing = ExistingOutput::WriteInPlace);

// Writes `bytes` to standard output and flushes it. Throws RuntimeError
// on a write error (a full device, a closed pipe).
void write_standard_output(std::string_view bytes);

// Flushes standard output (what printf wrote so far). Throws RuntimeError
// "cannot write to standard output: <reason>" if it cannot.
void flush_standard_output();

}  // namespace penumbra
