// The error column (--panels error): a run with e^n = u^n - u_e(t_n) added.
#include "core/error_column.hpp"

#include "core/error.hpp"

namespace vibra {

namespace {
class ErrorColumn final : public Trajectory {
 public:
  ErrorColumn(std::unique_ptr<Trajectory> run, TrajectoryInfo info) : Trajectory(std::move(info)), run_(std::move(run)) {}

  double t() const override { return run_->t(); }
  long long index() const override { return run_->index(); }
  bool done() const override { return run_->done(); }
  bool advance() override { return run_->advance(); }
  bool bends_between_samples() const override { return run_->bends_between_samples(); }
  void row(std::span<double> out) const override {
    run_->row(out.first(run_->width()));
    add_error(out);
  }
  void row_at(double t, std::span<double> out) const override {
    run_->row_at(t, out.first(run_->width()));
    add_error(out);
  }

 private:
  void add_error(std::span<double> out) const { out[run_->width()] = out[1] - info_.exact(out[0]); }

  std::unique_ptr<Trajectory> run_;
};
}  // namespace

std::unique_ptr<Trajectory> with_error_column(std::unique_ptr<Trajectory> run) {
  TrajectoryInfo info = run->info();
  if (!info.exact || info.exact_label != "exact")
    throw UsageError("panel 'error' needs an exact solution, and this run has " +
                     std::string(info.exact ? "only an approximate one (" + info.exact_label + ")" : "none") +
                     ": drop it (undamped always has one; vibration with a linear spring and no forcing, or a sine "
                     "force without damping; resonance; two-body's circular orbit)");
  info.columns.push_back("error");
  return std::make_unique<ErrorColumn>(std::move(run), std::move(info));
}

}  // namespace vibra
