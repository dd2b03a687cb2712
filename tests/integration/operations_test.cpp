// Running next to a simulator and failing well: an external ego (a simulator's stand-in started
// on its own), a service killed during a run, and peers that never show up.
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

constexpr int kDomainExternal = test_domain::kOperationsExternal;
constexpr int kDomainKilled = test_domain::kOperationsKilled;
constexpr int kDomainMissing = test_domain::kOperationsMissing;

// Starts a command in the background with its output in a file; returns its pid.
pid_t spawn(const std::vector<std::string>& argv, const std::string& out_path) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(out, STDERR_FILENO);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  return pid;
}

int wait_exit(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

bool wait_for_text(const std::string& path, const std::string& text, int seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    if (file_bytes(path).find(text) != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

TEST(Operations, ASimulatorPublishingTheEgoStateReplacesTheStandIn) {
  const std::string dir = fresh_dir("external");
  const std::string domain = std::to_string(kDomainExternal);
  const std::string scenario = source("scenarios/freeway.pbtxt");
  const pid_t launcher = spawn({bin("entourage"), "run", scenario, "--realtime", "--external-ego", "--duration", "8",
                                "--domain", domain, "--record", dir + "/x.mcap", "--quiet"},
                               dir + "/launcher.out");
  // The "simulator": the stand-in started on its own, as a simulator would publish the topic. It
  // drives on well past the run (a loaded machine may take seconds to discover) and is stopped after.
  const pid_t simulator = spawn({bin("entourage-ego"), "--scenario", scenario, "--mode", "realtime", "--duration", "60",
                                 "--domain", domain, "--peers", "ego,generator,micro,meso,director,recorder"},
                                dir + "/simulator.out");
  EXPECT_EQ(wait_exit(launcher), 0) << file_bytes(dir + "/launcher.out");
  ::kill(simulator, SIGTERM);
  wait_exit(simulator);
  const std::string out = file_bytes(dir + "/launcher.out");
  EXPECT_NE(out.find("services: generator, micro, meso, director, recorder"), std::string::npos) << out;
  std::string error;
  const auto rec = recording::read_recording(dir + "/x.mcap", &error);
  ASSERT_TRUE(rec) << error;
  EXPECT_GE(rec->egos.size(), 80U);
  EXPECT_GT(rec->vehicles.size(), 1000U);
  EXPECT_TRUE(no_process_uses_domain(kDomainExternal));
  std::filesystem::remove_all(dir);
}

TEST(Operations, AServiceThatDiesFailsTheRunWithItsName) {
  const std::string dir = fresh_dir("killed");
  const pid_t launcher = spawn({bin("entourage"), "run", source("scenarios/freeway.pbtxt"), "--realtime", "--duration",
                                "600", "--domain", std::to_string(kDomainKilled), "--record", dir + "/k.mcap",
                                "--quiet"},
                               dir + "/launcher.out");
  ASSERT_TRUE(wait_for_text(dir + "/k.logs/ego.log", "driving", 60)) << file_bytes(dir + "/launcher.out");
  const CommandResult pid = run_command("pgrep -f -- 'entourage-micr[o] .*--domain " + std::to_string(kDomainKilled) + " '");
  ASSERT_EQ(pid.exit_code, 0) << pid.output;
  ::kill(std::stoi(pid.output), SIGKILL);
  EXPECT_EQ(wait_exit(launcher), 1);
  const std::string out = file_bytes(dir + "/launcher.out");
  EXPECT_NE(out.find("micro exited with code 137"), std::string::npos) << out;
  EXPECT_TRUE(no_process_uses_domain(kDomainKilled));
  std::filesystem::remove_all(dir);
}

TEST(Operations, MissingPeersAreNamedWhenDiscoveryTimesOut) {
  const std::string dir = fresh_dir("missing");
  // No simulator ever publishes the ego state.
  const CommandResult r = run_command(bin("entourage") + " run " + source("scenarios/freeway.pbtxt") +
                                      " --external-ego --discovery-timeout 3 --domain " +
                                      std::to_string(kDomainMissing) + " --record " + dir + "/m.mcap --quiet");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("not ready"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("ego (external simulator: no ego state yet)"), std::string::npos) << r.output;
  EXPECT_TRUE(no_process_uses_domain(kDomainMissing));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace entourage::testing
