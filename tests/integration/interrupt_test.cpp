// Ctrl-C (SIGINT) or SIGTERM during a run: every service stops cleanly, no process is left, the
// recording so far is complete and readable, and the launcher exits with 130.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "process_util.hpp"
#include "../test_domains.hpp"
#include "recording/recording.hpp"

namespace entourage::testing {
namespace {

constexpr int kDomain = test_domain::kInterrupt;
constexpr std::uintmax_t kRecordedBytes = 256 * 1024;

TEST(Interrupt, CtrlCStopsEverythingCleanly) {
  const std::string dir = fresh_dir("interrupt");
  const std::string record = dir + "/i.mcap";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int out = ::open((dir + "/launcher.out").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(out, STDERR_FILENO);
    const std::string exe = bin("entourage");
    const std::string scenario = source("scenarios/freeway.pbtxt");
    const std::string domain = std::to_string(kDomain);
    ::execl(exe.c_str(), exe.c_str(), "run", scenario.c_str(), "--realtime", "--duration", "600", "--domain",
            domain.c_str(), "--record", record.c_str(), "--quiet", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Wait (polling) until the run is under way: the ego stand-in reports that it drives.
  const std::string ego_log = dir + "/i.logs/ego.log";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (file_bytes(ego_log).find("driving") == std::string::npos && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_NE(file_bytes(ego_log).find("driving"), std::string::npos) << file_bytes(dir + "/launcher.out");
  // Let it record a little: poll until the recording holds some steps' worth of samples (it is
  // written as they arrive; one freeway step is some 10 KB).
  const auto recorded = [&] {
    std::error_code ec;
    const auto size = std::filesystem::file_size(record, ec);
    return !ec && size >= kRecordedBytes;
  };
  while (!recorded() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(recorded()) << file_bytes(dir + "/launcher.out");
  ::kill(pid, SIGINT);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << file_bytes(dir + "/launcher.out");
  EXPECT_TRUE(no_process_uses_domain(kDomain));
  std::string error;
  const auto rec = recording::read_recording(record, &error);
  ASSERT_TRUE(rec) << error;
  EXPECT_GT(rec->egos.size(), 5U);
  EXPECT_NE(file_bytes(dir + "/launcher.out").find("interrupted"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace entourage::testing
