#pragma once
// The subcommands of `entourage` (a contract: other tools and tests call them).

namespace entourage::launcher {

int run_command(int argc, char** argv);     // entourage run SCENARIO [options]
int check_command(int argc, char** argv);   // entourage check SCENARIO
int export_command(int argc, char** argv);  // entourage export RECORDING --csv DIR
int verify_command(int argc, char** argv);  // entourage verify RECORDING|CSV_DIR
int models_command(int argc, char** argv);  // entourage models

}  // namespace entourage::launcher
