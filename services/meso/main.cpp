// entourage-meso: the outer regions' mesoscopic simulation as a DDS service (see README.md).
#include <spdlog/spdlog.h>

#include "dds/region_shell.hpp"
#include "meso/core/meso_core.hpp"

namespace entourage {

int meso_main(int argc, char** argv) {
  std::string regions = "both";
  bool carried_states = false;
  return dds::service_main(
      argc, argv, ServiceId{Role::kMeso, kMesoBoth},
      "The outer regions: a cheap mesoscopic model between the inner region and the window's edges.",
      [&regions, &carried_states](cli::Args& args) {
        args.option("regions", "WHICH", "both, front or rear: the outer regions this instance serves (default both)",
                    &regions);
        args.flag("carried-states",
                  "publish only the vehicle states a reader cannot carry forward from the last it got; readers carry "
                  "the others forward (lockstep only)",
                  &carried_states);
      },
      [&carried_states](const dds::ServiceContext& ctx) {
        if (carried_states && ctx.options.time_mode != dds::TimeMode::kLockstep) {
          spdlog::error("--carried-states needs --mode lockstep: in real time a reader may not get every step of "
                        "this service, and could not carry its states forward");
          return 2;
        }
        meso::MesoCore core(ctx.scenario.config, ctx.id);
        const int rc = dds::run_region_service(ctx, core, carried_states);
        const meso::Counters& c = core.counters();
        spdlog::info("vehicles adopted {}; handed to micro {}, to the other meso {}, to the front zone {}; retired {}, taken off by the director {}; "
                     "planned at {} of {} steps, {} vehicle plans ({} of alert vehicles between updates), "
                     "{} of them floor-gap emergencies; "
                     "mandatory lane changes {}, changes called off {}; overtakings started {}; "
                     "director commands applied {}; duplicate handoffs {}",
                     c.adopted, c.to_micro, c.to_other_meso, c.to_front_zone, c.retired, c.taken_off, c.planning_steps, c.steps,
                     c.plans, c.alert_plans, c.emergency_stops, c.mandatory_lane_changes, c.called_off_lane_changes,
                     c.overtakings_started, c.commands_applied, c.duplicate_handoffs);
        return rc;
      },
      [&regions](ServiceId* id) -> std::optional<std::string> {
        if (regions == "both") id->instance = kMesoBoth;
        else if (regions == "front") id->instance = kMesoFront;
        else if (regions == "rear") id->instance = kMesoRear;
        else return "--regions must be both, front or rear";
        return std::nullopt;
      });
}

}  // namespace entourage

int main(int argc, char** argv) { return entourage::meso_main(argc, argv); }
