#pragma once
// Reading a file that could be anything a path can name: a FIFO that never
// opens, a device that never ends (/dev/zero, /dev/urandom), a folder, or a
// regular file far larger than any sound input. Only a regular file of at
// most `max_bytes` is read, and never more than that.
#include <cstddef>
#include <string>

namespace penumbra {

// The whole file. Opens without blocking (a FIFO with no writer), then
// checks it is a regular file no larger than `max_bytes`, and reads at most
// that many bytes (a file that grows while read is cut off and refused).
// Throws RuntimeError "<what> '<path>': <why>".
std::string read_bounded_file(const std::string& path, std::size_t max_bytes,
                              const std::string& what);

}  // namespace penumbra
