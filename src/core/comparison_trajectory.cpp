// The runs of a comparison as one Trajectory, columns suffixed by member.
#include "core/comparison_trajectory.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace vibra {

namespace {
/// `u[rk4]` for a scheme comparison, `u[dt=0.05]` for any other key.
std::string member_column(const std::string& column, const Comparison& c, size_t i) {
  const std::string& key = c.request().key;
  return column + "[" + (key == "scheme" ? c.value(i) : key + "=" + c.value(i)) + "]";
}
}  // namespace

ComparisonTrajectory::ComparisonTrajectory(const ModelDefinition& model, const Parameters& base,
                                           ComparisonRequest request)
    : Trajectory({}),
      comparison_(model, base, std::move(request)),
      members_(comparison_.size()),
      early_ends_(std::make_shared<std::vector<EarlyEnd>>(comparison_.size(), EarlyEnd::none)) {
  comparison_.set_view_limits();
  const TrajectoryInfo& first = comparison_.trajectory(0).info();
  TrajectoryInfo info;
  info.columns = {"t"};
  info.mesh = first.mesh;
  info.small_period_label = first.small_period_label;
  size_t widest = 0;
  for (size_t i = 0; i < comparison_.size(); ++i) {
    const TrajectoryInfo& member = comparison_.trajectory(i).info();
    offsets_.push_back(info.columns.size());
    for (size_t c = 1; c < member.columns.size(); ++c) info.columns.push_back(member_column(member.columns[c], comparison_, i));
    widest = std::max(widest, member.columns.size());
    info.mesh.dt = std::min(info.mesh.dt, member.mesh.dt);
    info.mesh.T = std::max(info.mesh.T, member.mesh.T);
    info.amplitude_bound = std::max(info.amplitude_bound, member.amplitude_bound);
    info.damped = info.damped || member.damped;
    info.rows_on_one_mesh = info.rows_on_one_mesh && member.rows_on_one_mesh && !member.mesh.adaptive() &&
                            member.mesh.dt == first.mesh.dt;
  }
  // About one sample per finest step; done() tells the true end.
  info.mesh.steps = std::isfinite(info.mesh.T) ? std::llround(info.mesh.T / info.mesh.dt) : first.mesh.steps;
  if (comparison_.same_problem()) {
    info.exact = first.exact;
    info.exact_label = first.exact_label;
    info.exact_period = first.exact_period;
    info.exact_period_label = first.exact_period_label;
  }
  info_ = std::move(info);
  scratch_.resize(widest);
  for (size_t i = 0; i < members_.size(); ++i) check_escape(i);
}

void ComparisonTrajectory::check_escape(size_t i) {
  Trajectory& run = comparison_.trajectory(i);
  const std::span<double> row(scratch_.data(), run.width());
  run.row(row);
  if (!comparison_.leaves_view(i, row)) return;
  members_[i].blow_up_time = run.t();
  (*early_ends_)[i] = std::isfinite(row[1]) ? EarlyEnd::left_view : EarlyEnd::blew_up;
}

bool ComparisonTrajectory::done() const {
  return std::none_of(members_.begin(), members_.end(), [](const MemberState& m) { return m.running(); });
}

bool ComparisonTrajectory::advance() {
  // Every member's step holds [t_, next sample]: members whose sample is at
  // t_ step on, the others are already past it.
  double next = INFINITY;
  for (size_t i = 0; i < members_.size(); ++i) {
    MemberState& m = members_[i];
    if (!m.running()) continue;
    Trajectory& run = comparison_.trajectory(i);
    if (run.t() <= t_) {
      try {
        if (!run.advance()) {
          m.finished = true;
          continue;
        }
      } catch (const SolutionError&) {  // non-finite: this member stops, the others go on
        m.blow_up_time = run.t() + run.info().mesh.dt;
        (*early_ends_)[i] = EarlyEnd::blew_up;
        continue;
      }
      check_escape(i);
    }
    next = std::min(next, run.t());
  }
  if (next == INFINITY) return false;
  t_ = next;
  ++index_;
  return true;
}

bool ComparisonTrajectory::bends_between_samples() const {
  for (size_t i = 0; i < comparison_.size(); ++i)
    if (comparison_.trajectory(i).bends_between_samples()) return true;
  return false;
}

void ComparisonTrajectory::hide_runs_between_their_samples(std::span<double> row) const {
  for (size_t i = 0; i < members_.size(); ++i) {
    const Trajectory& run = comparison_.trajectory(i);
    if (run.bends_between_samples() || row[0] == run.t()) continue;
    const auto columns = row.subspan(offsets_[i], run.width() - 1);
    std::fill(columns.begin(), columns.end(), NAN);
  }
}

void ComparisonTrajectory::straight_samples_ahead(std::vector<std::vector<double>>& out) const {
  size_t n = 0;
  for (size_t i = 0; i < members_.size(); ++i) {
    const Trajectory& run = comparison_.trajectory(i);
    if (run.bends_between_samples() || !(run.t() < members_[i].blow_up_time)) continue;
    if (out.size() <= n) out.emplace_back();
    std::vector<double>& ahead = out[n++];
    ahead.assign(width(), NAN);
    const std::span<double> member(scratch_.data(), run.width());
    run.row(member);
    ahead[0] = member[0];
    std::copy(member.begin() + 1, member.end(), ahead.begin() + offsets_[i]);
  }
  out.resize(n);
}

void ComparisonTrajectory::row_at(double t, std::span<double> out) const {
  out[0] = t;
  for (size_t i = 0; i < members_.size(); ++i) {
    const Trajectory& run = comparison_.trajectory(i);
    const std::span<double> member(scratch_.data(), run.width());
    if (t >= members_[i].blow_up_time) std::fill(member.begin(), member.end(), NAN);
    else if (t == run.t()) run.row(member);
    else run.row_at(t, member);
    std::copy(member.begin() + 1, member.end(), out.begin() + offsets_[i]);
  }
}

}  // namespace vibra
