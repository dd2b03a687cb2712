#pragma once
// Child processes of the launcher: each service runs as its own process, in its own process
// group (so that Ctrl-C reaches only the launcher, which then stops the services in order), with
// its output in a log file, and dies with the launcher if the launcher itself is killed.

#include <sys/types.h>

#include <optional>
#include <string>
#include <vector>

namespace entourage::launcher {

class Child {
 public:
  Child(std::string name, std::vector<std::string> argv, std::string log_path);
  ~Child();  // kills the process if it is still running
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  bool start(std::string* error);
  // Non-blocking: updates and returns whether the process is still running.
  bool running();
  void signal(int sig);
  // Waits up to timeout_s for the process to end; false if it is still running.
  bool wait(double timeout_s);

  const std::string& name() const { return name_; }
  const std::string& log_path() const { return log_path_; }
  pid_t pid() const { return pid_; }
  // Exit code (or 128 + signal) once ended.
  std::optional<int> exit_code() const { return exit_code_; }
  bool killed_by_us() const { return killed_by_us_; }
  // The CPU time the process has used so far (user and system, all its threads; Linux's
  // /proc/<pid>/stat, in clock ticks of 10 ms); nullopt once it has ended or where it cannot be read.
  std::optional<double> cpu_s() const;
  // The last lines of the log, for error messages.
  std::string log_tail(std::size_t lines) const;

 private:
  std::string name_;
  std::vector<std::string> argv_;
  std::string log_path_;
  pid_t pid_ = -1;
  std::optional<int> exit_code_;
  bool killed_by_us_ = false;
};

// Did the process abort on Fast DDS 2.9.1's assertion in PDP::check_remote_participant_liveliness
// (named in the last `log_lines` of its log)? That assertion fails when a peer leaves the domain
// just as the lease timer of that peer fires (the peer's record is cleared before the timer gets
// the lock): it happens only as participants leave, after their work is done.
bool aborted_in_fastdds_lease_race(const Child& c, std::size_t log_lines);

}  // namespace entourage::launcher
