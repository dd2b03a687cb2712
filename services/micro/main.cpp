// entourage-micro: the inner region's microscopic simulation as a DDS service (see README.md).
#include "dds/region_shell.hpp"
#include "micro/core/micro_core.hpp"

namespace entourage {

int micro_main(int argc, char** argv) {
  return dds::service_main(
      argc, argv, ServiceId{Role::kMicro, 0},
      "The inner region: car following (IDM, modified IDM, Gipps, with the Human Driver Model), lane changes (MOBIL, mandatory) and overtakings in the oncoming lane of every vehicle near the ego.", nullptr,
      [](const dds::ServiceContext& ctx) {
        micro::MicroCore core(ctx.scenario.config, ctx.id);
        return dds::run_region_service(ctx, core);
      });
}

}  // namespace entourage

int main(int argc, char** argv) { return entourage::micro_main(argc, argv); }
