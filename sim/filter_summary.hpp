// The GNSS/INS filter's configuration as `run` and `mc` write it in summary.json (docs/aided.md,
// "Outputs"): its model file, its states per sensor axis, the white-noise densities it carries
// and the known errors it compensates — what the filter actually used of the model file.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "sim/aided/aiding_config.hpp"

namespace sinsim::sim {

/// summary.json's "filter" object of an enabled filter.
nlohmann::json filterSummaryJson(const aided::FilterConfig& filter);

/// The same in one line for the terminal: "filter: 9 navigation + 18 sensor states from MODEL;
/// compensated as known: gyro.triad[0].misalignment, ..." (the known part only when there is one).
std::string filterSummaryLine(const aided::FilterConfig& filter);

}  // namespace sinsim::sim
