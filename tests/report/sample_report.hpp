// A sample report exercising every block and plot element (log-log Allan deviation with a model
// band and shaded failing τ-ranges, PSD, ACF, Monte Carlo envelopes, tables with highlighted
// cells). The numbers are closed forms plus seeded pseudo-noise, not a real sensor.
#pragma once

#include "sim/report/report.hpp"

namespace sinsim::report::testing {

HtmlPage samplePage();

}  // namespace sinsim::report::testing
