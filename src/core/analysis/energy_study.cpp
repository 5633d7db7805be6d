// The chapter's energy-error table: one entry per scheme and T.
#include "core/analysis/energy_study.hpp"

#include <cmath>
#include <cstdio>

#include "core/analysis/energy.hpp"
#include "core/models/model.hpp"

namespace vibra {

namespace {
std::string exact_text(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}
}  // namespace

std::vector<EnergyError> energy_error_table(const std::vector<std::string>& schemes, const std::vector<double>& Ts,
                                            const std::vector<double>& dts) {
  const ModelDefinition& undamped = find_model("undamped");
  std::vector<EnergyError> table;
  for (const auto& scheme : schemes)
    for (double T : Ts)
      for (double dt : dts) {
        Parameters p = model_parameters(undamped);
        p.set("scheme", scheme);
        p.set("T", exact_text(T));
        p.set("dt", exact_text(dt));
        p.set("I", "1");
        p.set("V", "0");
        p.set("w", "2*pi");
        auto trajectory = undamped.build(p);
        table.push_back({scheme, T, dt, max_relative_energy_error(*trajectory, 2 * M_PI, 1, 0)});
      }
  return table;
}

}  // namespace vibra
