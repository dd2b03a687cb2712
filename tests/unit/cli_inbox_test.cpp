// The command-line parser and the service inbox (what arrives over DDS, by step).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "cli/args.hpp"
#include "dds/inbox.hpp"
#include "dds/region_shell.hpp"
#include "dds_test_util.hpp"
#include "traffic/carried_states.hpp"
#include "road/road.hpp"

namespace entourage {
namespace {

TEST(Args, ParsesOptionsFlagsAndPositionals) {
  std::string scenario;
  std::string out = "default";
  double duration = -1.0;
  int domain = 0;
  std::uint64_t seed = 0;
  bool quiet = false;
  cli::Args a("prog", "summary");
  a.positional("SCENARIO", "file", &scenario);
  a.option("out", "FILE", "output", &out);
  a.option("duration", "S", "duration", &duration);
  a.option("domain", "ID", "domain", &domain);
  a.option("seed", "N", "seed", &seed);
  a.flag("quiet", "quiet", &quiet);
  ASSERT_TRUE(a.parse({"x.pbtxt", "--duration", "12.5", "--domain=7", "--seed", "42", "--quiet"})) << a.error();
  EXPECT_EQ(scenario, "x.pbtxt");
  EXPECT_EQ(out, "default");
  EXPECT_DOUBLE_EQ(duration, 12.5);
  EXPECT_EQ(domain, 7);
  EXPECT_EQ(seed, 42U);
  EXPECT_TRUE(quiet);
  EXPECT_TRUE(a.was_set("seed"));
  EXPECT_FALSE(a.was_set("out"));
}

TEST(Args, NamesWhatIsWrong) {
  std::string s;
  int n = 0;
  std::uint64_t seed = 0;
  cli::Args a("prog", "summary");
  a.positional("FILE", "file", &s);
  a.option("count", "N", "count", &n);
  a.option("seed", "N", "seed", &seed);
  EXPECT_FALSE(a.parse({"f", "--count", "3x"}));
  EXPECT_NE(a.error().find("--count"), std::string::npos);
  cli::Args b("prog", "summary");
  b.positional("FILE", "file", &s);
  EXPECT_FALSE(b.parse({"--nope"}));
  EXPECT_NE(b.error().find("unknown option --nope"), std::string::npos);
  cli::Args c("prog", "summary");
  c.positional("FILE", "file", &s);
  EXPECT_FALSE(c.parse({}));
  EXPECT_NE(c.error().find("missing FILE"), std::string::npos);
  cli::Args d("prog", "summary");
  d.option("seed", "N", "seed", &seed);
  EXPECT_FALSE(d.parse({"--seed", "-3"}));
}

dds::SampleLimits limits() {
  dds::SampleLimits l;
  l.lanes_forward = 2;
  l.lanes_backward = 2;
  l.vehicle_types = 1;
  return l;
}

msg::VehicleState vehicle(std::uint32_t id, std::uint64_t step, ServiceId owner) {
  msg::VehicleState m;
  m.id(id);
  m.step(step);
  m.owner(owner.code());
  m.direction(1);
  m.length_m(4.5);
  m.width_m(1.8);
  m.speed_mps(30.0);
  return m;
}

constexpr ServiceId kEgo{Role::kEgo, 0};
constexpr ServiceId kMicro{Role::kMicro, 0};
constexpr ServiceId kMeso{Role::kMeso, 0};

// What every executable does first: 2 with the error on a bad argument, 0 on --help, go on otherwise.
TEST(Args, ParseOrExitGivesTheExitCodeToStopWith) {
  const auto run = [](std::vector<std::string> words) {
    int n = 0;
    cli::Args a("prog", "summary");
    a.option("count", "N", "count", &n);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    ::testing::internal::CaptureStderr();
    ::testing::internal::CaptureStdout();
    const std::optional<int> rc = a.parse_or_exit(static_cast<int>(argv.size()), argv.data());
    const std::string err = ::testing::internal::GetCapturedStderr();
    const std::string out = ::testing::internal::GetCapturedStdout();
    return std::make_tuple(rc, err, out);
  };
  const auto [bad, bad_err, bad_out] = run({"prog", "--count", "x"});
  EXPECT_EQ(bad, std::optional<int>(2));
  EXPECT_EQ(bad_err.rfind("prog: ", 0), 0U) << bad_err;
  EXPECT_NE(bad_err.find("usage: prog"), std::string::npos);
  EXPECT_TRUE(bad_out.empty());
  const auto [help, help_err, help_out] = run({"prog", "--help"});
  EXPECT_EQ(help, std::optional<int>(0));
  EXPECT_NE(help_out.find("usage: prog"), std::string::npos);
  EXPECT_TRUE(help_err.empty());
  const auto [good, good_err, good_out] = run({"prog", "--count", "3"});
  EXPECT_FALSE(good.has_value());
  EXPECT_TRUE(good_err.empty() && good_out.empty());
}

TEST(Inbox, AStepIsCompleteWhenEverythingAnnouncedHasArrived) {
  dds::Inbox in({kEgo, kMicro, kMeso}, kMicro, limits());
  dds::TopicCounts two{};
  two[static_cast<std::size_t>(dds::Topic::kVehicleState)] = 2;
  const dds::TopicMask mask = dds::mask_of(dds::Topic::kVehicleState);
  in.add(dds::make_step_done(kEgo, 3, {}, 0));
  in.add(dds::make_step_done(kMeso, 3, two, 2));
  EXPECT_FALSE(in.complete(3, mask));
  in.add(vehicle(1, 3, kMeso));
  in.add(vehicle(2, 3, kMeso));
  EXPECT_TRUE(in.complete(3, mask));
  EXPECT_EQ(in.take(3).vehicles.size(), 2U);
  EXPECT_TRUE(in.take(3).vehicles.empty());  // taken once
}

// A publisher that carries its states forward (traffic/carried_states.hpp): the inbox rebuilds, when
// it takes a step, every state the publisher did not write, and drops the vehicles it has no more.
TEST(Inbox, TheStatesAPublisherCarriesForwardAreRebuiltStepByStep) {
  const double dt = 0.1;
  const Road road(dds::testing::road_config());
  dds::Inbox in({kEgo, kMicro, kMeso}, kMicro, limits());
  in.carry_states(dds::testing::road_config(), dt);
  Vehicle v;
  v.id = 5;
  v.s_m = 1000.0;
  v.speed_mps = 20.0;
  v.accel_mps2 = 1.0;
  const auto carried_report = [](Step step, std::uint32_t written, std::vector<std::uint32_t> gone) {
    dds::TopicCounts counts{};
    counts[static_cast<std::size_t>(dds::Topic::kVehicleState)] = written;
    msg::StepDone d = dds::make_step_done(kMeso, step, counts, 1);
    d.carried_states(true);
    d.gone(std::move(gone));
    return d;
  };
  const VehicleReport first(v, Region::kOuterFront);
  in.add(dds::to_msg(first, kMeso, 0, 0.0, road));
  in.add(carried_report(0, 1, {}));
  ASSERT_EQ(in.take(0).vehicles.size(), 1U);
  VehicleReport expected = first;
  for (Step k = 1; k <= 3; ++k) {  // nothing written: carried forward
    in.add(carried_report(k, 0, {}));
    expected = carried_forward(expected, dt);
    const dds::Bucket b = in.take(k);
    ASSERT_EQ(b.vehicles.size(), 1U) << k;
    EXPECT_EQ(b.vehicles.front(), dds::to_msg(expected, kMeso, k, static_cast<double>(k) * dt, road)) << k;
  }
  EXPECT_DOUBLE_EQ(expected.speed_mps, 20.3);
  in.add(carried_report(4, 0, {5}));  // gone
  EXPECT_TRUE(in.take(4).vehicles.empty());
}

TEST(Inbox, OwnSamplesAreIgnored) {
  dds::Inbox in({kEgo, kMicro}, kMicro, limits());
  in.add(vehicle(1, 0, kMicro));
  EXPECT_TRUE(in.take(0).vehicles.empty());
}

TEST(Inbox, BadSamplesAreCountedDroppedAndStillCompleteTheStep) {
  dds::Inbox in({kEgo, kMeso}, kEgo, limits());
  dds::TopicCounts one{};
  one[static_cast<std::size_t>(dds::Topic::kVehicleState)] = 1;
  in.add(dds::make_step_done(kMeso, 5, one, 1));
  msg::VehicleState bad = vehicle(9, 5, kMeso);
  bad.s_m(std::numeric_limits<double>::quiet_NaN());
  in.add(bad);
  EXPECT_EQ(in.bad_samples(), 1U);
  EXPECT_TRUE(in.complete(5, dds::mask_of(dds::Topic::kVehicleState)));  // a bad sample does not stall lockstep
  EXPECT_TRUE(in.take(5).vehicles.empty());
}

TEST(Inbox, TheRecorderKeepsBadSamples) {
  dds::Inbox in({kEgo, kMeso}, ServiceId{Role::kRecorder, 0}, limits(), /*keep_refused=*/true);
  msg::VehicleState bad = vehicle(9, 5, kMeso);
  bad.lane(7);
  in.add(bad);
  EXPECT_EQ(in.bad_samples(), 1U);
  EXPECT_EQ(in.take(5).vehicles.size(), 1U);
}

TEST(Inbox, LateHandoffsAreNeverDropped) {
  dds::Inbox in({kEgo, kMeso}, kMicro, limits());
  msg::Handoff h;
  h.vehicle_id(4);
  h.handoff_sequence(2);
  h.step(2);
  h.from_service(kMeso.code());
  h.direction(1);
  h.length_m(4.5);
  h.width_m(1.8);
  h.driver().desired_speed_mps(30.0);
  h.driver().time_gap_s(1.5);
  h.driver().max_accel_mps2(1.0);
  h.driver().comfort_decel_mps2(1.5);
  in.add(h);
  in.forget_before(10);  // step 2 is long gone, but the handoff is kept
  const auto late = in.take_handoffs_upto(10);
  ASSERT_EQ(late.size(), 1U);
  EXPECT_EQ(late[0].vehicle_id(), 4U);
}

constexpr ServiceId kDirector{Role::kDirector, 0};

msg::ActorCommand command(std::uint32_t vehicle_id, std::uint64_t step, std::uint8_t mode = 2) {
  ActorCommand c;
  c.vehicle = vehicle_id;
  c.step = step;
  c.control.mode = static_cast<ControlMode>(mode);
  c.control.play_id = 1;
  c.control.speed_mps = 20.0;
  return dds::to_msg(c, 0.1 * static_cast<double>(step));
}

TEST(Inbox, AStepWaitsForEveryCommandTheDirectorAnnounced) {
  dds::Inbox in({kEgo, kMicro, kDirector}, kMicro, limits());
  dds::TopicCounts two{};
  two[static_cast<std::size_t>(dds::Topic::kActorCommand)] = 2;
  const dds::TopicMask mask = dds::mask_of(dds::Topic::kVehicleState) | dds::mask_of(dds::Topic::kActorCommand);
  in.add(dds::make_step_done(kEgo, 3, {}, 0));
  in.add(command(5, 3));
  in.add(dds::make_step_done(kDirector, 3, two, 0));
  EXPECT_FALSE(in.complete(3, mask));
  EXPECT_NE(in.missing(3, mask).find("1/2 entourage/actor_command"), std::string::npos) << in.missing(3, mask);
  in.add(command(4, 3));
  EXPECT_TRUE(in.complete(3, mask));
  const auto taken = in.take_commands_upto(3);
  ASSERT_EQ(taken.size(), 2U);
  EXPECT_TRUE(in.take_commands_upto(3).empty());  // taken once
  EXPECT_TRUE(in.take(3).commands.empty());
}

TEST(Inbox, BadCommandsAreCountedDroppedAndStillCompleteTheStep) {
  dds::Inbox in({kEgo, kDirector}, kMeso, limits());
  dds::TopicCounts one{};
  one[static_cast<std::size_t>(dds::Topic::kActorCommand)] = 1;
  in.add(dds::make_step_done(kEgo, 6, {}, 0));
  in.add(dds::make_step_done(kDirector, 6, one, 0));
  in.add(command(5, 6, /*mode=*/9));
  EXPECT_EQ(in.bad_samples(), 1U);
  EXPECT_TRUE(in.complete(6, dds::mask_of(dds::Topic::kActorCommand)));
  EXPECT_TRUE(in.take_commands_upto(6).empty());
}

TEST(Inbox, LateCommandsAreNeverDropped) {
  dds::Inbox in({kEgo, kDirector}, kMicro, limits());
  in.add(command(8, 2));
  in.forget_before(10);  // step 2 is long gone, but the command is kept
  EXPECT_EQ(in.steps_with_samples_before(11), std::vector<Step>{10});
  const auto late = in.take_commands_upto(10);
  ASSERT_EQ(late.size(), 1U);
  EXPECT_EQ(late[0].vehicle_id(), 8U);
  EXPECT_EQ(late[0].step(), 2U);
}

msg::EgoState ego_state(std::uint64_t step) {
  msg::EgoState m;
  m.step(step);
  m.direction(1);
  m.speed_mps(30.0);
  m.length_m(4.6);
  m.width_m(1.8);
  return m;
}

TEST(GatherInputs, CommandsOfThePreviousStepByVehicleThenStep) {
  dds::Inbox in({kEgo, kMeso, kDirector}, kMicro, limits());
  in.add(ego_state(4));
  in.add(ego_state(5));
  in.add(command(9, 2));  // late: arrived after its step
  in.forget_before(4);
  in.add(command(9, 4));
  in.add(command(3, 4));
  in.add(command(6, 5));  // written at step 5: for step 6
  const StepInput input = dds::gather_inputs(5, in, {});
  ASSERT_EQ(input.commands.size(), 3U);
  EXPECT_EQ(input.commands[0].vehicle, 3U);
  EXPECT_EQ(input.commands[1].vehicle, 9U);
  EXPECT_EQ(input.commands[1].step, 2U);
  EXPECT_EQ(input.commands[2].vehicle, 9U);
  EXPECT_EQ(input.commands[2].step, 4U);
  EXPECT_EQ(input.commands[2].control.mode, ControlMode::kControlled);
  EXPECT_DOUBLE_EQ(input.commands[2].control.speed_mps, 20.0);
  const auto next = in.take_commands_upto(5);
  ASSERT_EQ(next.size(), 1U);
  EXPECT_EQ(next[0].vehicle_id(), 6U);
}

}  // namespace
}  // namespace entourage
