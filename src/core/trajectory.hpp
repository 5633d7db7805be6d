// Trajectory: a model's run for observers, rows of columns with the exact solution and the state between samples.
#pragma once
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/energy_parts.hpp"
#include "core/math/hermite.hpp"
#include "core/math/linear_between.hpp"
#include "core/solution_stream.hpp"
#include "core/time_mesh.hpp"

namespace vibra {

/// What a model tells its observers besides the numbers.
struct TrajectoryInfo {
  std::vector<std::string> columns;  ///< first column is t, second the main quantity
  TimeMesh mesh;
  /// Largest |value| the main quantity can reach (from energy), 0 if unknown.
  double amplitude_bound = 0;
  /// Exact solution of the main quantity where known (empty otherwise).
  std::function<double(double t)> exact;
  std::string exact_label;  ///< e.g. "exact" or "small-angle"
  /// The true period of the main quantity where known (the pendulum's
  /// 4 K(sin(Theta/2)), not its small-angle 2 pi), 0 otherwise. The
  /// small-oscillation period is mesh.period.
  double exact_period = 0;
  std::string exact_period_label;  ///< how that period is known, as a formula: "2π/ω", "4K(sin Θ/2)"
  /// The small-oscillation period (mesh.period) as a formula, e.g. "2π/ω".
  std::string small_period_label = "2π/ω";
  /// True when drag, friction or a dashpot takes energy out of the system.
  bool damped = false;
  /// True when a force depends on the velocity throughout (a dashpot, a
  /// resistor, drag; not friction, which only flips with its sign): set
  /// from the system. Some schemes lose order then (damped_order).
  bool velocity_damping = false;
  /// Kinetic and potential energy from a row, with the scheme's own velocity
  /// (empty for a model without a mechanical energy). With an external force
  /// the energy is not conserved: E - E(0) then includes the force's work.
  EnergyFunction energy;
  std::string energy_unit;  ///< what the energy is measured in, e.g. "m g L"
  /// The power of the external force (F·v from a row, in the energy's unit
  /// per time unit): its integral is the work in E - E(0). Empty for a model
  /// without an external force.
  std::function<double(std::span<const double> row)> forcing_power;
  /// A restoring force against friction, drawn against u by `--panels
  /// friction` (the sliding box, Exercise 1.23a): the spring force s(u) and
  /// the kinetic friction mu, both in units of the initial spring force.
  struct SpringAndFriction {
    std::function<double(double u)> spring;
    double mu = 0;
  };
  std::optional<SpringAndFriction> spring_and_friction;
  /// False when rows are not all mesh points of one fixed-step mesh (a
  /// comparison of runs with different dt or an adaptive member).
  bool rows_on_one_mesh = true;
};

/// The step dt of the mesh every row lies on (t_n = n dt, and an impact's
/// instant where a model has events), or 0 when the rows are an adaptive
/// run's or a comparison's of several meshes: what a plot marks as the
/// scheme's own points.
inline double fixed_mesh_step(const TrajectoryInfo& info) {
  return info.rows_on_one_mesh && !info.mesh.adaptive() ? info.mesh.dt : 0;
}

/// The column holding the main quantity's velocity: v<name> where the model
/// has it (vx for x), else the column after the main quantity (v for u, omega for theta).
int velocity_column(const TrajectoryInfo&);

/// A model's solution as a stream of table rows, with the scheme and the
/// dimension erased: the CSV writer, frame sampler and ASCII plotter read it.
class Trajectory {
 public:
  virtual ~Trajectory() = default;
  const TrajectoryInfo& info() const { return info_; }
  size_t width() const { return info_.columns.size(); }

  virtual double t() const = 0;
  virtual long long index() const = 0;
  /// Whether the last sample has been reached.
  virtual bool done() const { return index() >= info_.mesh.steps; }
  /// Next time step; false at the end. Throws SolutionError on blow-up.
  virtual bool advance() = 0;
  /// The columns at the current sample.
  virtual void row(std::span<double> out) const = 0;
  /// The columns at time t between the previous and the current sample: for
  /// a fixed-step scheme the mesh values joined by straight lines
  /// (core/math/linear_between.hpp); for an adaptive one its dense output where
  /// it has one (dopri5), else quintic Hermite interpolation (core/math/hermite.hpp).
  virtual void row_at(double t, std::span<double> out) const = 0;
  /// Whether rows between samples leave the straight line between them (an
  /// adaptive scheme's dense output, an impact inside a step): only then
  /// does a drawing need rows between samples to show the run.
  virtual bool bends_between_samples() const { return info_.mesh.adaptive(); }

  /// A row of several runs side by side (a comparison's members) holds each
  /// at the row's time, between its own samples or not. Sets to NaN the
  /// columns of every run that is straight between its samples and has none
  /// at row[0], so that a reader of samples (a curve, a sum) sees each such
  /// run at its own samples only, as it is drawn: joined by straight lines.
  /// A single run's rows are its own samples: nothing to hide.
  virtual void hide_runs_between_their_samples(std::span<double> row) const { (void)row; }
  /// For each run straight between its samples, its next sample at or after
  /// the current time: a row with t = that sample's time and the run's
  /// columns (the other runs' NaN). A single fixed-step run's is its current
  /// sample; a run that bends between its samples has none.
  virtual void straight_samples_ahead(std::vector<std::vector<double>>& out) const {
    out.resize(bends_between_samples() ? 0 : 1);
    if (out.empty()) return;
    out[0].resize(width());
    row(out[0]);
  }

 protected:
  explicit Trajectory(TrajectoryInfo info) : info_(std::move(info)) {}
  TrajectoryInfo info_;
};

/// The Trajectory of a SecondOrderSystem<D>; `to_row` turns a sample into the
/// model's columns (t first).
template <int D>
class SecondOrderTrajectory final : public Trajectory {
 public:
  using RowFunction = std::function<void(const Sample<D>&, std::span<double>)>;

  SecondOrderTrajectory(std::shared_ptr<const SecondOrderSystem<D>> system, const Vec<D>& u0, const Vec<D>& v0,
                        TrajectoryInfo info, RowFunction to_row)
      : Trajectory(std::move(info)),
        system_(std::move(system)),
        stream_(make_stepper<D>(info_.mesh.scheme, *system_, u0, v0, info_.mesh.dt, info_.mesh.control()),
                info_.mesh.adaptive() ? SolutionStream<D>::unbounded : info_.mesh.steps,
                info_.mesh.adaptive() ? info_.mesh.T : std::numeric_limits<double>::infinity()),
        previous_(stream_.current()),
        to_row_(std::move(to_row)) {
    info_.velocity_damping = system_->damping != Damping::none;
  }

  double t() const override { return stream_.current().t; }
  long long index() const override { return stream_.index(); }
  bool done() const override { return stream_.done(); }
  bool advance() override {
    previous_ = stream_.current();
    return stream_.advance();
  }
  void row(std::span<double> out) const override { to_row_(stream_.current(), out); }
  void row_at(double t, std::span<double> out) const override { to_row_(interpolate(t), out); }

  const SecondOrderSystem<D>& system() const { return *system_; }
  SolutionStream<D>& stream() { return stream_; }

 private:
  Sample<D> interpolate(double t) const {
    const Sample<D>& a = previous_;
    const Sample<D>& b = stream_.current();
    if (b.t - a.t <= 0 || t >= b.t) return b;
    if (t <= a.t) return a;
    if (!info_.mesh.adaptive()) return linear_between<D>(a, b, t);
    if (auto dense = stream_.dense_at(t)) return *dense;
    return hermite_between<D>(a, system_->acceleration(a.u, a.v, a.t), b, system_->acceleration(b.u, b.v, b.t), t);
  }

  std::shared_ptr<const SecondOrderSystem<D>> system_;
  SolutionStream<D> stream_;
  Sample<D> previous_;
  RowFunction to_row_;
};

}  // namespace vibra
