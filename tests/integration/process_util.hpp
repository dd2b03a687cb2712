#pragma once
// Running the real executables from tests: a command's exit code and output, temporary
// directories, and files compared byte for byte.

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace entourage::testing {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

inline CommandResult run_command(const std::string& command) {
  CommandResult r;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return r;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.output.append(buffer, n);
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

inline std::string bin(const std::string& name) { return std::string(ENTOURAGE_BINARY_DIR) + "/bin/" + name; }
inline std::string source(const std::string& path) { return std::string(ENTOURAGE_SOURCE_DIR) + "/" + path; }

inline std::string fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("entourage_it_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// No process of this test is left over (each test uses its own DDS domain).
inline bool no_process_uses_domain(int domain) {
  // [n]: the pattern must not match the shell that runs pgrep with it
  return run_command("pgrep -f -- '--domai[n] " + std::to_string(domain) + " '").exit_code == 1;
}

}  // namespace entourage::testing
