// entourage-meso: the outer regions' mesoscopic simulation as a DDS service (see README.md).
#include "dds/region_shell.hpp"
#include "meso/core/meso_core.hpp"

namespace entourage {

int meso_main(int argc, char** argv) {
  std::string regions = "both";
  return dds::service_main(
      argc, argv, ServiceId{Role::kMeso, kMesoBoth},
      "The outer regions: a cheap mesoscopic model between the inner region and the window's edges.",
      [&regions](cli::Args& args) {
        args.option("regions", "WHICH", "both, front or rear: the outer regions this instance serves (default both)",
                    &regions);
      },
      [](const dds::ServiceContext& ctx) {
        meso::MesoCore core(ctx.scenario.config, ctx.id);
        return dds::run_region_service(ctx, core);
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
