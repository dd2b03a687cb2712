// The launcher's child processes: exit codes, logs, and the one abort it tolerates when a service
// leaves the DDS domain (Fast DDS 2.9.1's lease race, services/launcher/README.md).
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

#include <unistd.h>

#include "launcher/process.hpp"

namespace entourage::launcher {
namespace {

constexpr std::size_t kTail = 15;  // as many log lines as the launcher reads
constexpr double kWait_s = 10.0;

// Per process: ctest runs each test of this file as its own process, in parallel, and one test's
// TearDown removed the log another was still reading (seen once in a full ctest run, and again
// within 20 repeats of this file's tests).
std::string log_path(const std::string& name) {
  const std::string file = "entourage_process_test_" + std::to_string(::getpid()) + "_" + name + ".log";
  return (std::filesystem::temp_directory_path() / file).string();
}

// Runs `script` with sh as a child of this process ($0 in it is `text`) and waits for it to end.
std::unique_ptr<Child> finished(const std::string& name, const std::string& script, const std::string& text = "") {
  auto c = std::make_unique<Child>(name, std::vector<std::string>{"/bin/sh", "-c", script, text}, log_path(name));
  std::string error;
  EXPECT_TRUE(c->start(&error)) << error;
  EXPECT_TRUE(c->wait(kWait_s));
  return c;
}

class LauncherProcess : public ::testing::Test {
 protected:
  void TearDown() override {
    for (const char* n : {"lease_race", "other_abort", "text_only", "killed", "busy"}) std::filesystem::remove(log_path(n));
  }
};

const char* kAssertionLine =
    "entourage-generator: ./src/cpp/rtps/builtin/discovery/participant/PDP.cpp:1140: void "
    "eprosima::fastrtps::rtps::PDP::check_remote_participant_liveliness(eprosima::fastrtps::rtps::"
    "ParticipantProxyData*): Assertion `GUID_t::unknown() != remote_participant->m_guid' failed.";

TEST_F(LauncherProcess, AnAbortOnFastDdsLeaseAssertionIsRecognised) {
  auto c = finished("lease_race", "echo 'left the domain' >&2; printf '%s\\n' \"$0\" >&2; kill -ABRT $$",
                    kAssertionLine);
  EXPECT_EQ(c->exit_code(), 128 + SIGABRT);
  EXPECT_TRUE(aborted_in_fastdds_lease_race(*c, kTail));
}

TEST_F(LauncherProcess, AnyOtherAbortIsNot) {
  auto c = finished("other_abort", "echo 'free(): double free detected' >&2; kill -ABRT $$");
  EXPECT_EQ(c->exit_code(), 128 + SIGABRT);
  EXPECT_FALSE(aborted_in_fastdds_lease_race(*c, kTail));
}

TEST_F(LauncherProcess, TheAssertionTextWithoutAnAbortIsNot) {
  // A service that logged the text but exited with an error code failed for its own reason.
  auto c = finished("text_only", "printf '%s\\n' \"$0\" >&2; exit 1", kAssertionLine);
  EXPECT_EQ(c->exit_code(), 1);
  EXPECT_FALSE(aborted_in_fastdds_lease_race(*c, kTail));
}

TEST_F(LauncherProcess, AProcessKilledByTheLauncherIsNot) {
  auto c = std::make_unique<Child>("killed", std::vector<std::string>{"/bin/sh", "-c", "sleep 30"}, log_path("killed"));
  std::string error;
  ASSERT_TRUE(c->start(&error)) << error;
  c->signal(SIGKILL);
  ASSERT_TRUE(c->wait(kWait_s));
  EXPECT_EQ(c->exit_code(), 128 + SIGKILL);
  EXPECT_TRUE(c->killed_by_us());
  EXPECT_FALSE(aborted_in_fastdds_lease_race(*c, kTail));
}

// The run's summary gives each service's CPU time per step from Child::cpu_s: a shell that counts
// (one thread, busy) shows CPU time that grows, never more than the wall time it has run, and none
// once it has ended.
TEST_F(LauncherProcess, TheCpuTimeOfARunningChildIsReadAndGrows) {
  Child c("busy", {"/bin/sh", "-c", "while :; do :; done"}, log_path("busy"));
  std::string error;
  ASSERT_TRUE(c.start(&error)) << error;
  const auto started = std::chrono::steady_clock::now();
  double cpu = 0.0;
  while (cpu < 0.2 && std::chrono::steady_clock::now() - started < std::chrono::duration<double>(kWait_s)) {
    const std::optional<double> now = c.cpu_s();
    ASSERT_TRUE(now) << "the CPU time of a running child could not be read";
    EXPECT_GE(*now, cpu);
    cpu = *now;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_GE(cpu, 0.2) << "a busy shell used no CPU time in " << wall_s << " s";
  EXPECT_LE(cpu, wall_s + 0.05) << "one busy thread cannot use more CPU time than the time it ran";
  c.signal(SIGKILL);
  ASSERT_TRUE(c.wait(kWait_s));
  EXPECT_FALSE(c.cpu_s()) << "an ended process has no CPU time to read";
}

}  // namespace
}  // namespace entourage::launcher
