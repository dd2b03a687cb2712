#pragma once
// Loading and checking scenario files (Protocol Buffers text format, schema scenario.proto).
// Every problem is reported with file, line, column and the field's path, so a user can fix a
// scenario from the message alone; a scenario with any problem is refused as a whole.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scenario/config.hpp"

namespace entourage::scenario {

class Scenario;  // generated from scenario.proto

struct Problem {
  std::string file;
  int line = 0;    // 1-based; 0 if unknown
  int column = 0;  // 1-based; 0 if unknown
  std::string field;  // e.g. "demand.forward.flow_veh_per_h"; empty for syntax errors
  std::string message;

  std::string to_string() const;  // "file:line:column: field: message"
};

struct Loaded {
  std::string path;
  std::string text;                 // the file as read (stored in recordings)
  std::shared_ptr<Scenario> proto;  // null if the file could not be parsed
  std::vector<Problem> problems;    // empty when the scenario is valid
  ScenarioConfig config;            // filled when there are no problems

  bool ok() const { return proto != nullptr && problems.empty(); }
};

// Reads, parses, validates and resolves a scenario file.
Loaded load_file(const std::string& path);
// The same for text already in memory; `path` only names the source in problems.
Loaded load_text(const std::string& text, const std::string& path);

}  // namespace entourage::scenario
