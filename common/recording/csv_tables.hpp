#pragma once
// The directory `entourage export` writes and `entourage verify` reads back: a recording's Tables
// as CSV files (the format of one file: csv_file.hpp; every column: README.md here).
//   vehicles.csv    one row per vehicle per step
//   ego.csv         one row per step
//   handoffs.csv    one row per ownership change
//   plays.csv       one row per play status report
//   commands.csv    one row per command of the director to an actor
//   run.csv         the run's settings, one row
//   scenario.pbtxt  the scenario the run was made with, as attached to the recording
// Numbers are written so that they read back as the same doubles: verify prints the same figures
// from the directory as from the recording.

#include <optional>
#include <string>

#include "recording/csv_file.hpp"
#include "recording/tables.hpp"

namespace entourage::recording {

extern const char* const kVehiclesFile;
extern const char* const kEgoFile;
extern const char* const kHandoffsFile;
extern const char* const kPlaysFile;
extern const char* const kCommandsFile;
extern const char* const kRunFile;
extern const char* const kScenarioFile;

extern const csv::Columns kVehicleColumns;
extern const csv::Columns kEgoColumns;
extern const csv::Columns kHandoffColumns;
extern const csv::Columns kPlayColumns;
extern const csv::Columns kCommandColumns;
extern const csv::Columns kRunColumns;

// Writes every file into `dir` (created if need be); false with *error if one cannot be written.
bool write_csv(const Tables& t, const std::string& dir, std::string* error);

// Reads every file of `dir` back, rows sorted as tables_from sorts them; nullopt with *error
// ("FILE:LINE:COLUMN: COLUMN_NAME: what is wrong") at the first problem.
std::optional<Tables> read_csv(const std::string& dir, std::string* error);

}  // namespace entourage::recording
