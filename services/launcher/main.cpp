// entourage: runs a scenario with every service as its own process, checks scenarios, exports
// and verifies recordings. See README.md.
#include <cstring>
#include <iostream>
#include <string>

#include "launcher/commands.hpp"

namespace {
const char* const kUsage =
    "usage: entourage <command> [arguments]\n"
    "\n"
    "commands:\n"
    "  run SCENARIO [--lockstep|--realtime] [--seed N] [--duration SECONDS] [--record FILE]\n"
    "                   start every service as a process, run the scenario, print a summary\n"
    "  check SCENARIO   validate a scenario; print every problem with file, line and field\n"
    "  export RECORDING --csv DIR\n"
    "                   write DIR/vehicles.csv, ego.csv, handoffs.csv, plays.csv, commands.csv, run.csv,\n"
    "                   scenario.pbtxt\n"
    "  verify RECORDING|DIR\n"
    "                   check a recording's (or its export's) invariants and print its figures\n"
    "  models           list the behavioural models a scenario can name\n"
    "\n"
    "`entourage <command> --help` shows a command's options.\n";
}  // namespace

int main(int argc, char** argv) {
  using namespace entourage::launcher;
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    std::cout << kUsage;
    return argc < 2 ? 2 : 0;
  }
  const std::string command = argv[1];
  if (command == "run") return run_command(argc, argv);
  if (command == "check") return check_command(argc, argv);
  if (command == "export") return export_command(argc, argv);
  if (command == "verify") return verify_command(argc, argv);
  if (command == "models") return models_command(argc, argv);
  std::cerr << "entourage: unknown command \"" << command << "\"\n\n" << kUsage;
  return 2;
}
