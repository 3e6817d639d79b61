// The option tables of the impact's rules (-impact_*) and of the monitors (-monitor_*,
// -snapshot_times), read by ImpactParamsFromOptions and MonitorRequestFromOptions
// (run/impact.hpp) and registered by app/registry.cpp.
#pragma once

#include "base/option_table.hpp"

namespace beamimpact {

const OptionModule &ImpactOptionTable();
const OptionModule &MonitorOptionTable();

} // namespace beamimpact
