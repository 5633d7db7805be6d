#include "app/experiments.hpp"
#include "app/list_option.hpp"
#include "core/analysis/energy_study.hpp"
#include "scenes/analysis_figures.hpp"

namespace vibra::app {

ExperimentResult energy_experiment(const EnergyOptions& o) {
  auto entries = energy_error_table(word_list("--schemes", o.schemes), positive_list("--T", o.T),
                                    positive_list("--dt", o.dt));
  Table table({"scheme", "T", "dt", "max_rel_energy_error"});
  for (const auto& e : entries) table.add_row({e.scheme, e.T, e.dt, e.max_relative_error});
  ExperimentResult result;
  result.tables.push_back({"max |e_E^n| / E(0), n = 1..Nt-1, for u'' + (2 pi)^2 u = 0, u(0) = 1, u'(0) = 0 "
                           "(u' by centered differences, as the book's table)",
                           std::move(table)});
  result.figure = [entries = std::move(entries)](int w, int h) { return scenes::energy_figure(entries, w, h); };
  return result;
}

}  // namespace vibra::app
