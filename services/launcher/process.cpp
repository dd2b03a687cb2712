#include "launcher/process.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstring>
#include <deque>
#include <fstream>
#include <sstream>
#include <thread>

namespace entourage::launcher {

namespace {
constexpr auto kPoll = std::chrono::milliseconds(20);
constexpr int kExecFailed = 127;
}  // namespace

Child::Child(std::string name, std::vector<std::string> argv, std::string log_path)
    : name_(std::move(name)), argv_(std::move(argv)), log_path_(std::move(log_path)) {}

Child::~Child() {
  if (pid_ > 0 && !exit_code_) {
    signal(SIGKILL);
    wait(5.0);
  }
}

bool Child::start(std::string* error) {
  const int log_fd = ::open(log_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log_fd < 0) {
    *error = "cannot create log file " + log_path_ + ": " + std::strerror(errno);
    return false;
  }
  std::vector<char*> args;
  for (auto& a : argv_) args.push_back(a.data());
  args.push_back(nullptr);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(log_fd);
    *error = std::string("fork failed: ") + std::strerror(errno);
    return false;
  }
  if (pid == 0) {
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(kExecFailed);  // the launcher died before prctl
    const int null_fd = ::open("/dev/null", O_RDONLY);
    ::dup2(null_fd, STDIN_FILENO);
    ::dup2(log_fd, STDOUT_FILENO);
    ::dup2(log_fd, STDERR_FILENO);
    ::execv(args[0], args.data());
    const std::string msg = std::string("cannot execute ") + args[0] + ": " + std::strerror(errno) + "\n";
    if (::write(STDERR_FILENO, msg.data(), msg.size()) < 0) ::_exit(kExecFailed);
    ::_exit(kExecFailed);
  }
  ::close(log_fd);
  ::setpgid(pid, pid);
  pid_ = pid;
  return true;
}

bool Child::running() {
  if (pid_ <= 0 || exit_code_) return false;
  int status = 0;
  const pid_t r = ::waitpid(pid_, &status, WNOHANG);
  if (r == pid_) {
    exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return false;
  }
  return true;
}

void Child::signal(int sig) {
  if (pid_ > 0 && !exit_code_) {
    if (sig == SIGKILL) killed_by_us_ = true;
    ::kill(pid_, sig);
  }
}

bool Child::wait(double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (running()) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(kPoll);
  }
  return true;
}

std::optional<double> Child::cpu_s() const {
  if (pid_ <= 0 || exit_code_) return std::nullopt;
  std::ifstream in("/proc/" + std::to_string(pid_) + "/stat");
  std::string stat;
  if (!std::getline(in, stat)) return std::nullopt;
  // The command name (field 2) is in parentheses and may hold spaces: count the fields after it,
  // from field 3 (the state) to 15 (stime); utime is field 14.
  const auto name_end = stat.rfind(')');
  if (name_end == std::string::npos) return std::nullopt;
  std::istringstream rest(stat.substr(name_end + 1));
  std::string skipped;
  for (int field = 3; field <= 13; ++field) rest >> skipped;
  unsigned long long user_ticks = 0;
  unsigned long long system_ticks = 0;
  rest >> user_ticks >> system_ticks;
  const long ticks_per_s = ::sysconf(_SC_CLK_TCK);
  if (!rest || ticks_per_s <= 0) return std::nullopt;
  return static_cast<double>(user_ticks + system_ticks) / static_cast<double>(ticks_per_s);
}

std::string Child::log_tail(std::size_t lines) const {
  std::ifstream in(log_path_);
  std::deque<std::string> last;
  std::string line;
  while (std::getline(in, line)) {
    last.push_back(line);
    if (last.size() > lines) last.pop_front();
  }
  std::string out;
  for (const auto& l : last) out += "    " + l + "\n";
  return out;
}

bool aborted_in_fastdds_lease_race(const Child& c, std::size_t log_lines) {
  return c.exit_code() == 128 + SIGABRT && !c.killed_by_us() &&
         c.log_tail(log_lines).find("check_remote_participant_liveliness") != std::string::npos;
}

}  // namespace entourage::launcher
