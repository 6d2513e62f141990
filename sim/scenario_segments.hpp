// The scenario's `segments:` list: each segment type's keys (a registry keyed by `type:`), the
// parse into specs whose targets are still symbolic, and their layout in time from the start
// state. Internal to sim/scenario*.cpp; the format is in docs/simulate.md ("Scenario files").
#pragma once

#include <vector>

#include "common/config.hpp"
#include "sim/motion.hpp"

namespace sinsim::sim::detail {

/// The segments of `segs` laid out back to back from t = 0, starting at `start`. Problems are
/// recorded on the nodes (file, line, key); nothing is laid out when a segment is invalid or
/// `file` already has problems (a bad start would produce follow-up messages about a state that
/// does not exist). Repeats are expanded; more than limits::kMaxSegments is an error.
std::vector<Segment> readSegments(const ConfigNode& segs, const MotionStart& start,
                                  const ConfigFile& file);

}  // namespace sinsim::sim::detail
