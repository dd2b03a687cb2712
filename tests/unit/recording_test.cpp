// Recordings: written in a fixed order (byte-identical for equal input), read back losslessly,
// exported to CSV and back. What is computed from them: recording_checks_test.cpp (the invariant
// checks), recording_figures_test.cpp (catch-up prediction, flow error, micro-meso transitions).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <unistd.h>

#include "core_test_util.hpp"
#include "recording/csv_tables.hpp"
#include "recording/recording.hpp"
#include "recording/tables.hpp"

namespace entourage::recording {
namespace {

namespace fs = std::filesystem;

std::string temp_path(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("entourage_recording_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

msg::VehicleState vehicle(std::uint32_t id, std::uint64_t step, double s, int lane, std::uint16_t owner = 0x0300,
                          std::uint8_t region = 2) {
  msg::VehicleState m;
  m.id(id);
  m.step(step);
  m.time_s(0.1 * static_cast<double>(step));
  m.owner(owner);
  m.region(region);
  m.direction(1);
  m.lane(static_cast<int16_t>(lane));
  m.target_lane(static_cast<int16_t>(lane));
  m.s_m(s);
  m.d_m(-1.75 - 3.5 * (1 - lane));
  m.speed_mps(30.0);
  m.length_m(4.5);
  m.width_m(1.8);
  return m;
}

msg::EgoState ego(std::uint64_t step, double s) {
  msg::EgoState m;
  m.step(step);
  m.time_s(0.1 * static_cast<double>(step));
  m.direction(1);
  m.s_m(s);
  m.d_m(-5.25);
  m.speed_mps(30.0);
  m.length_m(4.6);
  m.width_m(1.8);
  return m;
}

RecordingInfo info() {
  RecordingInfo i;
  i.scenario_name = "test";
  i.scenario_file = "test.pbtxt";
  i.scenario_text = "name: \"test\"\n";
  i.seed = 5;
  i.mode = "lockstep";
  i.step_s = 0.1;
  i.peers = "ego,micro";
  return i;
}

msg::ActorCommand command(std::uint32_t vehicle_id, std::uint64_t step, double speed) {
  msg::ActorCommand m;
  m.vehicle_id(vehicle_id);
  m.step(step);
  m.time_s(0.1 * static_cast<double>(step));
  m.play_id(4);
  m.mode(2);  // controlled
  m.speed_mps(speed);
  m.accel_mps2(1.5);
  m.decel_mps2(6.0);
  m.max_jerk_mps3(2.0);
  m.lane(1);
  m.force_lane(true);
  m.lane_change_duration_s(2.5);
  m.indicator(1);
  return m;
}

void write(const std::string& path, bool shuffled) {
  RecordingWriter w;
  ASSERT_TRUE(w.open(path, info())) << w.error();
  for (std::uint64_t k = 0; k < 3; ++k) {
    StepSamples s;
    s.step = k;
    s.time_s = 0.1 * static_cast<double>(k);
    s.ego = ego(k, 1000.0 + 3.0 * static_cast<double>(k));
    s.vehicles = {vehicle(7, k, 1100.0, 0), vehicle(3, k, 900.0, 1, 0x0400, 1)};
    s.vehicles[0].control(k == 2 ? 2 : 0);  // vehicle 7 under the director's control at step 2
    if (k == 1) s.commands = {command(7, 1, 20.0), command(3, 1, 25.0)};
    if (shuffled) {
      std::swap(s.vehicles[0], s.vehicles[1]);
      std::reverse(s.commands.begin(), s.commands.end());
    }
    w.write_step(s);
  }
  ASSERT_TRUE(w.close());
}

std::string bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

TEST(Recording, ArrivalOrderDoesNotChangeTheFile) {
  write(temp_path("a.mcap"), false);
  write(temp_path("b.mcap"), true);
  EXPECT_EQ(bytes(temp_path("a.mcap")), bytes(temp_path("b.mcap")));
}

TEST(Recording, ReadsBackEverySampleAndTheScenario) {
  write(temp_path("c.mcap"), false);
  std::string error;
  const auto r = read_recording(temp_path("c.mcap"), &error);
  ASSERT_TRUE(r) << error;
  EXPECT_EQ(r->egos.size(), 3U);
  EXPECT_EQ(r->vehicles.size(), 6U);
  EXPECT_EQ(r->undecodable, 0U);
  EXPECT_EQ(r->info.scenario_text, "name: \"test\"\n");
  EXPECT_EQ(r->info.seed, 5U);
  EXPECT_EQ(r->info.peers, "ego,micro");
  EXPECT_DOUBLE_EQ(r->vehicles[0].s_m(), 1100.0);  // sorted by owner: micro (0x0300) before meso
  ASSERT_EQ(r->commands.size(), 2U);
  EXPECT_EQ(r->commands[0].vehicle_id(), 3U);  // sorted by vehicle
  EXPECT_EQ(r->commands[1].vehicle_id(), 7U);
  EXPECT_EQ(r->commands[1].step(), 1U);
  EXPECT_EQ(r->commands[1].speed_mps(), 20.0);
  EXPECT_TRUE(r->commands[1].force_lane());
}

TEST(Recording, CsvExportRoundTrips) {
  write(temp_path("d.mcap"), false);
  std::string error;
  const auto r = read_recording(temp_path("d.mcap"), &error);
  ASSERT_TRUE(r) << error;
  const Tables t = tables_from(*r, {"car"});
  const std::string dir = temp_path("csv");
  ASSERT_TRUE(write_csv(t, dir, &error)) << error;
  std::ifstream v(dir + "/vehicles.csv");
  std::string header;
  std::getline(v, header);
  EXPECT_EQ(header,
            "step,time_s,id,owner,region,direction,lane,s_m,d_m,x_m,y_m,heading_rad,speed_mps,accel_mps2,length_m,width_m,"
            "type,target_lane,control");
  std::ifstream c(dir + "/commands.csv");
  std::string command_header;
  std::string command_row;
  std::getline(c, command_header);
  std::getline(c, command_row);
  EXPECT_EQ(command_header,
            "step,time_s,vehicle_id,play_id,mode,speed_mps,accel_mps2,decel_mps2,max_jerk_mps3,lane,force_lane,"
            "lane_change_duration_s,indicator");
  EXPECT_EQ(command_row, "1,0.1,3,4,controlled,25,1.5,6,2,1,1,2.5,1");
  const auto back = read_csv(dir, &error);
  ASSERT_TRUE(back) << error;
  ASSERT_EQ(back->vehicles.size(), 6U);
  EXPECT_EQ(back->vehicles[0].id, 3U);  // rows sorted by step, then id
  EXPECT_EQ(back->vehicles[0].owner, "meso");
  EXPECT_EQ(back->vehicles[0].region, "outer_rear");
  EXPECT_EQ(back->vehicles[0].type, "car");
  EXPECT_EQ(back->vehicles[0].control, "autonomous");
  EXPECT_EQ(back->vehicles[5].id, 7U);
  EXPECT_EQ(back->vehicles[5].control, "controlled");
  EXPECT_EQ(back->ego.size(), 3U);
  ASSERT_EQ(back->commands.size(), 2U);
  const CommandRow& cmd = back->commands[1];
  EXPECT_EQ(cmd.step, 1U);
  EXPECT_EQ(cmd.time_s, 0.1);
  EXPECT_EQ(cmd.vehicle_id, 7U);
  EXPECT_EQ(cmd.play_id, 4U);
  EXPECT_EQ(cmd.mode, "controlled");
  EXPECT_EQ(cmd.speed_mps, 20.0);
  EXPECT_EQ(cmd.accel_mps2, 1.5);
  EXPECT_EQ(cmd.decel_mps2, 6.0);
  EXPECT_EQ(cmd.max_jerk_mps3, 2.0);
  EXPECT_EQ(cmd.lane, 1);
  EXPECT_TRUE(cmd.force_lane);
  EXPECT_EQ(cmd.lane_change_duration_s, 2.5);
  EXPECT_EQ(cmd.indicator, 1U);
}

}  // namespace
}  // namespace entourage::recording
