// vibra analyze fd-accuracy: how well [DtDt u] approximates u'' (Exercise 1.8).
#include <cmath>

#include "jobs/experiments/experiments.hpp"
#include "core/analysis/fd_accuracy.hpp"
#include "core/error.hpp"
#include "scenes/figures/analysis_figures.hpp"

namespace vibra::app {

ExperimentResult fd_accuracy_experiment(const FdAccuracyOptions& o) {
  if (o.points < 2 || o.points > 100000)
    throw UsageError("--points must be 2..100000 (values of p from 0 to pi), e.g. --points 21");
  Table table({"p", "E", "taylor"});
  for (int i = 0; i < o.points; ++i) {
    const double p = M_PI * i / (o.points - 1);
    table.add_row({p, fd_accuracy(p), fd_accuracy_taylor(p)});
  }
  ExperimentResult result;
  result.tables.push_back({"Accuracy of the centered difference for u'' (Exercise 1.8): E(p) = [DtDt u]/u'' = "
                           "4 sin^2(p/2)/p^2, p = w dt from 0 to pi, and its Taylor polynomial 1 - p^2/12 + p^4/360",
                           std::move(table)});
  result.conclusion = "E(p) < 1 for p > 0: the difference underestimates u'', by the fraction p^2/12 for small p";
  result.figure = [](int width, int height) { return scenes::fd_accuracy_figure(width, height); };
  return result;
}

}  // namespace vibra::app
