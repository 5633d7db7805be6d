// The chapter's experiments (`vibra analyze ...`, `vibra.convergence(...)`): each takes its options as the user typed them, checks them (UsageError with the option's name), runs, and returns its tables and its figure.
// The defaults are the command line's.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "jobs/table.hpp"
#include "render/plot/figure.hpp"

namespace vibra::app {

/// A table with the line that says what it holds.
struct TitledTable {
  std::string heading;
  Table table;
};

struct ExperimentResult {
  std::vector<TitledTable> tables;
  /// A sentence under the tables saying what they show, e.g. whether the
  /// convergence rates have settled; "" for none.
  std::string conclusion;
  std::function<render::Figure(int width, int height)> figure;
};

/// Checks a figure path (FILE.png, .svg or .pdf in a writable directory; ""
/// for none) and a size "WxH" before an experiment runs, so that a long run
/// does not end in a refused path. Throws UsageError / OutputError.
void check_figure_output(const std::string& figure, const std::string& size);
/// Writes the result's figure at `figure` (nothing for "") in size "WxH".
void write_figure(const ExperimentResult&, const std::string& figure, const std::string& size);

struct ConvergenceOptions {
  std::string model;
  std::vector<std::string> settings;  ///< KEY=VALUE; dt (or steps_per_period) is the first level's
  /// Number of dt values, 2..20; none: halve dt until the last two rates
  /// settle (kAutoMinLevels to kAutoMaxLevels levels). The conclusion says
  /// whether they have.
  std::optional<int> levels;
  /// "scheme=A,B,...": one study per scheme, in one table (a scheme column
  /// first) and one log-log figure with a line per scheme (Fig 1.1); "" for one.
  std::string compare;
};
ExperimentResult convergence_experiment(const ConvergenceOptions&);

struct EnergyOptions {
  std::string schemes = "forward-euler,backward-euler,crank-nicolson,rk2,rk4,euler-cromer";
  std::string T = "1,10";
  std::string dt = "0.05,0.025,0.0125";
  /// Adds the column `rate`: ln(E_{i-1}/E_i) / ln(dt_{i-1}/dt_i) between
  /// successive dt of a scheme and T (Exercise 1.9).
  bool rates = false;
};
ExperimentResult energy_experiment(const EnergyOptions&);

struct EmpiricalOptions {
  std::string model;
  std::vector<std::string> settings;
  std::string dt;  ///< comma-separated; "" = the one run the settings describe
  bool mesh_extrema = false;
};
ExperimentResult empirical_experiment(const EmpiricalOptions&);

struct FrequencyOptions {
  std::string w = "1";
  std::string steps_per_period = "80,60,40,30,20,15,10,8,6,5,4";
};
ExperimentResult frequency_experiment(const FrequencyOptions&);

struct FdAccuracyOptions {
  int points = 21;  ///< values of p = w dt, evenly from 0 to pi
};
ExperimentResult fd_accuracy_experiment(const FdAccuracyOptions&);

struct AmplitudeOptions {
  std::string schemes = "forward-euler,backward-euler,crank-nicolson,rk2,rk4";
  std::string dt = "0.025";
  std::string periods = "10";
};
ExperimentResult amplitude_experiment(const AmplitudeOptions&);

struct OrbitOptions {
  std::string scheme = "pefrl";
  std::string steps_per_orbit = "200,400,800,1600";
  long long orbits = 100;
  /// Also PEFRL over 100000 orbits per steps-per-orbit value, with the error
  /// growth fitted and extrapolated to 1e9 orbits: a second table.
  bool long_run = false;
};
ExperimentResult orbit_experiment(const OrbitOptions&);

struct PeriodOptions {
  std::string model;
  std::vector<std::string> settings;
};
/// Each period between upward zero crossings against the exact one; the log decrement when damped.
ExperimentResult period_experiment(const PeriodOptions&);

struct ResonanceOptions {
  std::string beta = "0.005,0.05,0.2";
  std::string gamma = "5,1.5,1.1,1";
};
/// Exercise 1.22: steady amplitudes of u'' + beta u' + u = sin(gamma t) against the formula.
ExperimentResult resonance_experiment(const ResonanceOptions&);

struct BouncesOptions {
  std::vector<std::string> settings;  ///< bouncing-ball KEY=VALUE
};
/// Exercise 1.24: every impact of the bouncing ball, located inside the step.
ExperimentResult bounces_experiment(const BouncesOptions&);

}  // namespace vibra::app
