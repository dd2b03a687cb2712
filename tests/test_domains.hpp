#pragma once
// The DDS domain of every test that starts real participants, in one list so that no two tests
// share one (tests run in parallel, and each checks for its leftover processes by domain).
//
// Every domain here stays at or below 101. Fast DDS listens on well-known ports
// 7400 + 250·domain + offsets (common/dds/domain_ports.hpp); from domain 102 on those lie
// inside Linux's ephemeral port range (32768-60999 by default), where the kernel also picks the
// random ports of every process's send sockets. A send socket that happens to hold a test's
// multicast discovery port first keeps that test's participants from ever discovering each other
// (seen once at stop 48, when the tests used domains 110-150: six processes in domain 130,
// "readers 0/5" for 60 s). Below 32768 no random port can take them; tests/unit/domain_ports_test.cpp
// checks every domain here against the default range as well.

#include "dds/domain_ports.hpp"

namespace entourage::testing::test_domain {

enum : int {
  kPipelineLockstep = 50,
  kPipelineSplit,
  kPipelineRealtime,
  kInterrupt,
  kBadInputService,
  kBadSyntax,
  kBadNegativeFlow,
  kBadZeroLanes,
  kBadUnknownModel,
  kRural,
  kOperationsExternal,
  kOperationsKilled,
  kOperationsMissing,
  kVerifyCsv,
  kEgoStops,
  kEgoFast,
  kEgoSlow,
  kRuralEgoSlow,
  kRuralEgoFast,
  kProbe,
  kRuralProbe,
  kFaultLossy,
  kFaultClean,
  kPlays,
  kLossyHandoff,
  kPipelineCarried,
  kFaultLossyCarried,
  kFaultCleanCarried,
  kSeveralPlays,
  kEnd  // one past the last
};

static_assert(kEnd - 1 <= dds::highest_clear_domain(dds::kLinuxEphemeralDefault),
              "a test domain's ports would fall in the ephemeral range");

}  // namespace entourage::testing::test_domain
