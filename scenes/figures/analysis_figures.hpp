// The figures of `vibra analyze`, one per experiment of the chapter.
// Each takes the experiment's numbers and lays them out; none computes physics
// except the formulas it illustrates (1.18), (1.19).
#pragma once
#include <string>
#include <vector>

#include "core/analysis/empirical.hpp"
#include "core/analysis/energy_study.hpp"
#include "core/analysis/line_fit.hpp"
#include "core/analysis/model_convergence.hpp"
#include "core/analysis/orbit_error.hpp"
#include "core/analysis/frequency/period_meter.hpp"
#include "render/plot/figure.hpp"

namespace vibra::scenes {

/// log-log E against dt, with a reference line of slope = the scheme's order.
render::Figure convergence_figure(const std::vector<ModelConvergence>&, const std::string& title, int width, int height);

/// max |e_E|/E(0) against dt on log-log axes, a line per scheme, a panel per T.
render::Figure energy_figure(const std::vector<EnergyError>&, int width, int height);

/// The cycles of one run, labelled (e.g. by its dt or scheme).
struct LabelledCycles {
  std::string label;
  std::vector<OscillationCycle> cycles;
};

/// Angular frequency 2 pi/p_i and amplitude a_i against i, a line per run, with
/// the reference frequency as a dashed line (the book's Figure 1.3).
render::Figure empirical_figure(const std::vector<LabelledCycles>&, double reference_w, const std::string& reference_label,
                                const std::string& title, int width, int height);

/// w~ of (1.18) and its series (1.19) against dt up to the stability limit
/// 2/w, and their relative error against steps per period (Figure 1.4).
render::Figure frequency_figure(double w, int width, int height);
/// E(p) = 4 sin^2(p/2)/p^2 on [0, pi] with its Taylor polynomial (Exercise 1.8).
render::Figure fd_accuracy_figure(int width, int height);

/// a_i/I against t_i on a log axis for every scheme, and below a_i - I for
/// the schemes that stay within 10% of I (Exercise 1.13).
render::Figure amplitude_figure(const std::vector<LabelledCycles>&, double I, const std::string& title, int width,
                                int height);

/// Maximum error against steps per orbit; with long runs, the error per block
/// of orbits against the orbits done, with each run's fitted power law.
/// Each measured period against i, with the exact period (dashed vermillion)
/// where known and the small-oscillation period (dashed grey) as lines.
render::Figure period_figure(const std::vector<MeasuredPeriod>&, double exact_period, double small_oscillation_period,
                             const std::string& title, int width, int height);

/// Max position error against steps per orbit; with long runs also their
/// phase error per block with the fitted lines (data and fit together) and
/// their energy error per block.
render::Figure orbit_figure(const std::vector<OrbitRun>& runs, const std::vector<OrbitRun>& long_runs,
                            const std::vector<Line>& long_fits, const std::string& title, int width, int height);

}  // namespace vibra::scenes
