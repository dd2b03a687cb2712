#pragma once
// A run's recording read back as tables, with the scenario it ran, for end-to-end tests.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "recording/checks.hpp"
#include "recording/recording.hpp"
#include "recording/tables.hpp"
#include "scenario/loader.hpp"

namespace entourage::testing {

struct RecordedRun {
  scenario::Loaded scenario;
  recording::Tables tables;
};

// Loads `scenario_path` and reads `recording_path` into `out`; a fatal test failure if either
// cannot be read (call it under ASSERT_NO_FATAL_FAILURE).
inline void read_run(const std::string& scenario_path, const std::string& recording_path, RecordedRun* out) {
  out->scenario = scenario::load_file(scenario_path);
  ASSERT_TRUE(out->scenario.ok());
  std::string error;
  const auto rec = recording::read_recording(recording_path, &error);
  ASSERT_TRUE(rec) << error;
  std::vector<std::string> types;
  for (const auto& t : out->scenario.config.vehicle_types) types.push_back(t.name);
  out->tables = recording::tables_from(*rec, types);
}

// Every invariant of the design holds in the run (no_overlap covers head-on collisions).
inline void expect_invariants(const RecordedRun& run) {
  const EgoConfig& ego = run.scenario.config.ego;
  for (const auto& c : recording::check_invariants(run.tables, ego)) {
    EXPECT_TRUE(c.passed) << c.name << ": " << c.detail;
  }
}

}  // namespace entourage::testing
