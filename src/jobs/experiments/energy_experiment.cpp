// vibra analyze energy: the chapter's energy-error table over schemes and T.
#include <cmath>

#include "jobs/experiments/experiments.hpp"
#include "jobs/list_option.hpp"
#include "core/analysis/energy_study.hpp"
#include "scenes/figures/analysis_figures.hpp"

namespace vibra::app {

ExperimentResult energy_experiment(const EnergyOptions& o) {
  auto entries = energy_error_table(word_list("--schemes", o.schemes), positive_list("--T", o.T),
                                    positive_list("--dt", o.dt));
  std::vector<std::string> columns = {"scheme", "T", "dt", "max_rel_energy_error"};
  if (o.rates) columns.push_back("rate");
  Table table(columns);
  for (size_t i = 0; i < entries.size(); ++i) {
    const EnergyError& e = entries[i];
    std::vector<Table::Cell> row = {e.scheme, e.T, e.dt, e.max_relative_error};
    if (o.rates) {
      // The rate against the row before, where that is the same scheme and T.
      const bool same = i > 0 && entries[i - 1].scheme == e.scheme && entries[i - 1].T == e.T;
      const EnergyError* before = same ? &entries[i - 1] : nullptr;
      row.push_back(before ? Table::Cell(std::log(before->max_relative_error / e.max_relative_error) /
                                         std::log(before->dt / e.dt))
                           : Table::Cell(std::string()));
    }
    table.add_row(std::move(row));
  }
  ExperimentResult result;
  result.tables.push_back({"max |e_E^n| / E(0), n = 1..Nt-1, for u'' + (2 pi)^2 u = 0, u(0) = 1, u'(0) = 0 "
                           "(u' by centered differences, as the book's table)",
                           std::move(table)});
  result.figure = [entries = std::move(entries)](int w, int h) { return scenes::energy_figure(entries, w, h); };
  return result;
}

}  // namespace vibra::app
