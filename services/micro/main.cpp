// entourage-micro: the inner region's microscopic simulation as a DDS service (see README.md).
#include <spdlog/spdlog.h>

#include "dds/region_shell.hpp"
#include "micro/core/micro_core.hpp"

namespace entourage {

int micro_main(int argc, char** argv) {
  return dds::service_main(
      argc, argv, ServiceId{Role::kMicro, 0},
      "The inner region: car following (IDM, modified IDM, Gipps, with the Human Driver Model), lane changes (MOBIL, mandatory) and overtakings in the oncoming lane of every vehicle near the ego.", nullptr,
      [](const dds::ServiceContext& ctx) {
        micro::MicroCore core(ctx.scenario.config, ctx.id);
        const int rc = dds::run_region_service(ctx, core);
        const micro::Counters& c = core.counters();
        spdlog::info("vehicles adopted {}, handed out {}; lane changes started {} ({} mandatory); overtakings started "
                     "{}, aborted {}; handoffs deferred while overtaking {} vehicle-steps; emergency regime {} "
                     "vehicle-steps; director commands applied {}; duplicate handoffs {}",
                     c.adopted, c.handed_out, c.lane_changes_started, c.mandatory_lane_changes, c.overtakings_started,
                     c.overtakings_aborted, c.handoffs_deferred, c.emergency_decisions, c.commands_applied,
                     c.duplicate_handoffs);
        return rc;
      });
}

}  // namespace entourage

int main(int argc, char** argv) { return entourage::micro_main(argc, argv); }
