// The --panels friction figure of the sliding box (Exercise 1.23a): spring force against u and the friction band.
#include "scenes/figures/friction_panel.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "scenes/panels/plot_panels.hpp"

namespace vibra::scenes {

namespace {
/// A run without friction turns at the same two points forever: past this
/// many, more markers would only cover the ones drawn.
constexpr size_t kMostTurns = 2000;
constexpr int kCurveSamples = 801;  // odd, so u = 0 is a sample
const render::SeriesStyle kBandStyle{render::palette::ink.with_alpha(0.7), 1.6, true, false};

}  // namespace

FrictionPanel::FrictionPanel(render::Figure& figure, std::vector<Member> members) : figure_(figure) {
  for (const Member& m : members)
    if (!m.info->spring_and_friction)
      throw UsageError("panel 'friction' draws a spring force against friction: only sliding-box has one");
  panel_ = figure.add_panel({"<i>s</i>(<i>u</i>) and ±<i>μ</i>, in units of <i>kI</i>", quantity_markup("u")});
  const bool single = members.size() == 1;
  for (const Member& m : members) {
    Run run{m, nullptr, nullptr, {}};
    run.curve = &figure.add_path(panel_, single ? "spring force <i>s</i>(<i>u</i>)" : m.label, {m.color, 2.2});
    run.turns_drawn = &figure.add_points(panel_, single ? "turning points" : "", {m.color, 0, false, true});
    runs_.push_back(std::move(run));
  }
  if (!single) figure.add_points(panel_, "turning points", {render::palette::ink, 0, false, true});  // a legend entry only
}

void FrictionPanel::observe(size_t member, std::span<const double> row) {
  Run& run = runs_[member];
  const double u = row[1], v = row[velocity_column(*run.member.info)];
  if (!std::isfinite(u) || !std::isfinite(v)) return;
  reach_ = std::max(reach_, std::abs(u));
  // A turn is where v comes to 0 or changes sign: the row nearer v = 0 holds it
  // (rows come a fraction of a pixel apart, so the error is far below one).
  std::optional<double> turn;
  if (!run.started) {
    if (v == 0) turn = u;
  } else if (run.previous_v != 0 && (v == 0 || (v > 0) != (run.previous_v > 0))) {
    turn = std::abs(v) < std::abs(run.previous_v) ? u : run.previous_u;
  }
  if (turn && run.turns.size() < kMostTurns) {
    run.turns.push_back(*turn);
    run.turns_drawn->add(*turn, run.member.info->spring_and_friction->spring(*turn));
  }
  run.started = true, run.previous_u = u, run.previous_v = v;
}

void FrictionPanel::finish() {
  const double reach = reach_ > 0 ? reach_ : 1;
  auto mu = [](const Run& run) { return run.member.info->spring_and_friction->mu; };
  const bool shared_band =
      std::all_of(runs_.begin(), runs_.end(), [&](const Run& run) { return mu(run) == mu(runs_.front()); });
  const std::string band_label = "friction ±<i>μ</i>: the box can rest where |<i>s</i>(<i>u</i>)| ≤ <i>μ</i>";
  if (!shared_band) figure_.add_points(panel_, band_label + " (each run's own)", kBandStyle);  // a legend entry only
  for (size_t m = 0; m < runs_.size(); ++m) {
    const TrajectoryInfo::SpringAndFriction& law = *runs_[m].member.info->spring_and_friction;
    for (int i = 0; i < kCurveSamples; ++i) {
      const double u = reach * (2.0 * i / (kCurveSamples - 1) - 1);
      runs_[m].curve->add(u, law.spring(u));
    }
    if (shared_band && m > 0) continue;
    render::SeriesStyle style = kBandStyle;
    if (!shared_band) style.color = runs_[m].member.color.with_alpha(0.7);
    for (const double sign : {1.0, -1.0}) {
      render::Series& band = figure_.add_path(panel_, shared_band && sign > 0 ? band_label : "", style);
      band.add(-reach, sign * law.mu);
      band.add(reach, sign * law.mu);
    }
  }
}

}  // namespace vibra::scenes
