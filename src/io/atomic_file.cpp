#include "io/atomic_file.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace penumbra {

namespace fs = std::filesystem;

std::string temporary_name(const std::string& path) {
  fs::path p(path);
  std::string name = ".";
  name.append(p.filename().string()).append(".tmp").append(std::to_string(getpid()));
  return (p.parent_path() / name).string();
}

void commit_temporary(const std::string& temporary, const std::string& path) {
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw RuntimeError("cannot write '" + path + "': " + ec.message());
  }
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
  const std::string temporary = temporary_name(path);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(temporary, ec);
      throw RuntimeError("cannot write '" + path + "'");
    }
  }
  commit_temporary(temporary, path);
}

}  // namespace penumbra
