#pragma once
// Small helpers the benchmark programs share.
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

namespace entourage::bench {

// Is `program` an executable found on PATH (a peer simulator, gnuplot)?
inline bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::stringstream ss(path);
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    std::error_code ec;
    if (!dir.empty() && std::filesystem::exists(std::filesystem::path(dir) / program, ec)) return true;
  }
  return false;
}

}  // namespace entourage::bench
