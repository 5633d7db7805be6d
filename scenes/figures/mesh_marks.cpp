// vibra plot --annotate mesh (Fig 1.12): where a scheme's unknowns live on the time mesh.
#include "scenes/figures/mesh_marks.hpp"

#include "core/error.hpp"
#include "scenes/panels/plot_panels.hpp"

namespace vibra::scenes {

namespace {
constexpr int kPixelsPerStep = 8;
constexpr long long kMostTicks = 24;  ///< labelled mesh points on the t axis, at most
}  // namespace

namespace {
[[noreturn]] void too_many_steps(const std::string& steps, int width) {
  throw UsageError("--annotate mesh marks every step, and " + steps + " steps do not fit " + std::to_string(width) +
                   " pixels (at most " + std::to_string(width / kPixelsPerStep) +
                   "): take fewer, e.g. --set steps_per_period=8 --set periods=2");
}
}  // namespace

MeshMarks::MeshMarks(const TrajectoryInfo& info, int width) : info_(info), width_(width) {
  if (!info.mesh.adaptive() && info.mesh.steps > width / kPixelsPerStep) too_many_steps(std::to_string(info.mesh.steps), width);
}

void MeshMarks::mark_panel(render::Figure& figure, int panel, int column, double factor, render::Color color) {
  const bool half_steps = info_.mesh.scheme == Scheme::staggered && column == velocity_column(info_) && column != 1;
  const std::string quantity = quantity_symbol(info_.columns[column]);
  const std::string label = half_steps ? quantity + "<sup><i>n</i>+1/2</sup> at <i>t</i><sub><i>n</i>+1/2</sub>"
                                       : quantity + "<sup><i>n</i></sup> at <i>t</i><sub><i>n</i></sub>";
  // Half-step dots lie off the curve (it draws the mean at t_n): a colour of their own.
  render::Series& series = figure.add_points(panel, label, {half_steps ? render::palette::vermillion : color, 0, false, true});
  dots_.push_back({&series, column, factor, half_steps, {}});
}

void MeshMarks::observe_step(std::span<const double> row) {
  // An adaptive run's steps are known only as they come.
  if (++steps_seen_ > width_ / kPixelsPerStep + 1) too_many_steps("more than " + std::to_string(width_ / kPixelsPerStep), width_);
  for (Dots& d : dots_) {
    std::pair<double, double> point{row[0], d.factor * row[d.column]};
    if (d.half_steps) {
      if (previous_.empty()) continue;  // v^{1/2} needs u^1
      const double dt = row[0] - previous_[0];
      point = {previous_[0] + dt / 2, d.factor * (row[1] - previous_[1]) / dt};
    }
    d.points.push_back(point);
    d.series->add(point.first, point.second);
  }
  previous_.assign(row.begin(), row.end());
}

std::vector<double> MeshMarks::ticks() const {
  std::vector<double> ticks;
  if (info_.mesh.adaptive() || info_.mesh.steps > kMostTicks) return ticks;
  for (long long n = 0; n <= info_.mesh.steps; ++n) ticks.push_back(std::min(n * info_.mesh.dt, info_.mesh.T));
  return ticks;
}

}  // namespace vibra::scenes
