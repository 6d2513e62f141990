// The time axis of a record after parsing: increasing, uniform (or listed irregular) time stamps,
// a sample rate an IMU record can have, and the window [skip, skip + duration) the user keeps.
// Internal to the record loader (record.cpp).
#pragma once

#include <cstddef>
#include <string>

#include "errormodels/stats/record.hpp"

namespace sinsim::errormodels::detail {

/// InputError "SOURCE[:LINE]: WHAT" (line 0: no line).
[[noreturn]] void recordError(const std::string& source, std::size_t line, const std::string& what);

/// Checks that time stamps increase and are uniform (or lists the irregular steps when allowed)
/// and sets rec.rate_hz; first_line is the file line of row 0.
void checkTime(Record& rec, std::size_t first_line, const RecordOptions& options);

/// A record's sample rate must be one an IMU record can have (limits::kMinRate..kMaxRate); `hint`
/// ends the message.
void checkRate(double rate, const std::string& source, const std::string& what,
               const std::string& hint = "");

/// Keeps the samples [skip, skip + duration) of the record (RecordOptions::skip_s, duration_s).
void applyWindow(Record& rec, const RecordOptions& options);

}  // namespace sinsim::errormodels::detail
