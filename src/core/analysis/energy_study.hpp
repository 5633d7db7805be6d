// The chapter's energy-error table: one entry per scheme and T.
#pragma once
#include <string>
#include <vector>

namespace vibra {

/// One entry of the chapter's energy-error table (docs/analysis.md).
struct EnergyError {
  std::string scheme;
  double T, dt;
  double max_relative_error;  ///< max_n |e_E^n| / E(0)
};

/// max |e_E^n| / E(0) for u'' + (2 pi)^2 u = 0, I = 1, V = 0 (the book's
/// table) for every scheme, T and dt, in that nesting order. Each run streams.
/// Throws UsageError for an unknown scheme or a dt above a scheme's limit.
std::vector<EnergyError> energy_error_table(const std::vector<std::string>& schemes, const std::vector<double>& Ts,
                                            const std::vector<double>& dts);

}  // namespace vibra
