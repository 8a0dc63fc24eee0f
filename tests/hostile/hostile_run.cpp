#include "hostile/hostile_run.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace penumbra::hostile {

namespace fs = std::filesystem;

std::string binary() {
  return "'" + std::string(PENUMBRA_BINARY) + "'";
}

Result shell(const std::string& line) {
  std::string command = line;
  for (std::size_t pos = 0; (pos = command.find("PENUMBRA", pos)) != std::string::npos;) {
    if (pos + 8 < command.size() && command[pos + 8] == '_') {  // PENUMBRA_GEOMETRY_BUDGET
      pos += 8;
      continue;
    }
    command.replace(pos, 8, binary());
    pos += binary().size();
  }
  const fs::path dir = fs::path(PENUMBRA_TEST_OUTPUT) / "hostile";
  fs::create_directories(dir);
  const std::string err_file = (dir / ("stderr-" + std::to_string(getpid()) + ".txt")).string();
  const std::string script = (dir / ("script-" + std::to_string(getpid()) + ".sh")).string();
  write_text(script, command + "\n");
  Result r;
  FILE* pipe = popen(("/bin/sh '" + script + "' 2>'" + err_file + "'").c_str(), "r");
  std::array<char, 4096> buffer{};
  for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) {
    r.out.append(buffer.data(), n);
  }
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.err = read_text(err_file);
  fs::remove(err_file);
  fs::remove(script);
  return r;
}

std::string fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(PENUMBRA_TEST_OUTPUT) / "hostile" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

pid_t spawn(const std::vector<std::string>& args, int stdout_fd, int stderr_fd) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_RDWR);
    dup2(stdout_fd >= 0 ? stdout_fd : null, 1);
    dup2(stderr_fd >= 0 ? stderr_fd : null, 2);
    std::vector<char*> argv;
    std::string program = PENUMBRA_BINARY;
    argv.push_back(program.data());
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(PENUMBRA_BINARY, argv.data());
    _exit(127);
  }
  return pid;
}

std::vector<pid_t> children_of(pid_t parent) {
  std::vector<pid_t> children;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || !std::all_of(name.begin(), name.end(), ::isdigit)) continue;
    std::ifstream in(entry.path() / "stat");
    std::string stat;
    std::getline(in, stat);
    // pid (comm) state ppid ...: comm may hold spaces, so read after ')'.
    const std::size_t close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 1));
    char state = 0;
    long ppid = 0;
    rest >> state >> ppid;
    if (ppid == parent) children.push_back(static_cast<pid_t>(std::stol(name)));
  }
  return children;
}

bool running(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!std::getline(in, stat)) return false;
  const std::size_t close = stat.rfind(')');
  return close != std::string::npos && close + 2 < stat.size() && stat[close + 2] != 'Z';
}

bool one_error_line(const std::string& text, const std::string& culprit) {
  return text.rfind("penumbra: error: ", 0) == 0 &&
         std::count(text.begin(), text.end(), '\n') == 1 && text.find(culprit) != std::string::npos;
}

bool ends_in_one_error_line(const std::string& text, const std::string& culprit) {
  const std::size_t last = text.size() >= 2 ? text.rfind('\n', text.size() - 2) : std::string::npos;
  const std::string last_line = text.substr(last == std::string::npos ? 0 : last + 1);
  return one_error_line(last_line, culprit) &&
         text.find("penumbra: error: ") == text.rfind("penumbra: error: ");
}

long lines_starting_with(const std::string& text, const std::string& prefix) {
  long count = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = text.find('\n', start);
    count += text.compare(start, prefix.size(), prefix) == 0;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return count;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace penumbra::hostile
