// What the diagnosis reads from and writes into the model file's text.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace sinsim::errormodels::diagnose::detail {

/// Effects of the model file on one channel (types), from its `all` and axis lists.
std::vector<std::string> modelEffectTypes(const std::string& modelText, int channel);

/// The `ar` effect of a channel at the record's rate [Hz] as [1, a1..ap], if the model has
/// exactly one.
std::optional<std::vector<double>> arOfChannel(const std::string& text, int channel, double rate);

/// Model text with effects appended per channel and the base noise of each channel scaled by
/// sqrt(variance factor).
/// arReplace[c]: when non-empty, the channel's `ar` effect gets these coefficients a1..ap and
/// driving sigma (last element, SI) instead of its own.
std::string editModel(const std::string& modelText,
                      const std::array<std::vector<std::string>, 6>& addYaml,
                      const std::array<double, 6>& varianceScale, const std::string& header,
                      const std::array<std::vector<double>, 6>& arReplace = {});

}  // namespace sinsim::errormodels::diagnose::detail
