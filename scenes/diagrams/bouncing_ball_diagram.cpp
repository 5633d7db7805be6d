// The bouncing ball's diagram (section 1.12.9): ground, ball and its velocity arrow.
#include "scenes/diagrams/bouncing_ball_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/draw/annotations.hpp"
#include "render/draw/contrast.hpp"
#include "render/draw/elements/machine_elements.hpp"
#include "render/draw/text.hpp"
#include "scenes/diagrams/diagram_registry.hpp"

namespace vibra::scenes {

namespace {
// Proportions of the drawing, in units of the highest point reached.
constexpr double kRadius = 0.07, kLongestVelocity = 0.42, kArrowOffset = 2.2;
constexpr double kWeightLength = 2.4;  ///< radii: mg's arrow (and N's at rest), the key's unit
// The tally of impacts: dots in rows of kTallyRow, right of the ball.
constexpr int kTallyRow = 8, kTallyMost = 40;  // beyond, the count alone
constexpr double kTallyLeft = 0.34, kTallySpacing = 0.045, kTallyDot = 0.014;
}  // namespace

BouncingBallDiagram::BouncingBallDiagram(double g, double period, std::function<double(double)> exact, SceneColors colors)
    : g_(g), period_(period), exact_(std::move(exact)), colors_(colors) {}

std::vector<PanelSpec> BouncingBallDiagram::panels() const {
  PanelSpec h{"<i>h</i>  height", {{"numerical", colors_.bob, [](std::span<const double> r) { return r[1]; }}}};
  if (exact_) h.series.push_back({"exact", colors_.gravity, [e = exact_](std::span<const double> r) { return e(r[0]); }, true});
  PanelSpec v{"<i>v</i>  velocity", {{"", colors_.bob, [](std::span<const double> r) { return r[2]; }}}};
  return {std::move(h), std::move(v)};
}

void BouncingBallDiagram::record_other(std::span<const double> row, WorldBox&) {
  highest_ = std::max(highest_, row[1]);
  fastest_ = std::max(fastest_, std::abs(row[2]));
}

void BouncingBallDiagram::record(std::span<const double> row, WorldBox& world) {
  record_other(row, world);
  seen_.see(ForceKind::weight);
  if (at_rest(row)) seen_.see(ForceKind::normal);
  // A step that ends moving up (or at rest) after moving down held an impact:
  // the previous row's parabola h + v s - g s^2/2 reaches 0 at s.
  if (!previous_.empty() && previous_[2] < 0 && row[2] >= 0) {
    const double h = previous_[1], v = previous_[2];
    impacts_.push_back(previous_[0] + (v + std::sqrt(v * v + 2 * g_ * h)) / g_);
  }
  previous_.assign(row.begin(), row.end());
}

void BouncingBallDiagram::finish_recording(WorldBox& world) {
  const double H = highest_ > 0 ? highest_ : 1;
  radius_ = kRadius * H;
  per_speed_ = fastest_ > 0 ? kLongestVelocity * H / fastest_ : 0;
  // The ball's top at its highest, the weight's and the tally's labels at
  // the sides, the hatching under the ground (no arrow goes below it).
  world.extend(Point(-0.75 * H, H + 2 * radius_ + 0.05 * H));
  world.extend(Point(0.75 * H, 0));
  world.extend(Point(0, -0.12 * H));
}

Arrow BouncingBallDiagram::velocity_arrow(std::span<const double> row) const {
  // From the ball's centre beside it; a downward arrow that would reach
  // below the ground is lifted to end on it (the ball about to land).
  Point from = ball_center(row) + Point(kArrowOffset * radius_, 0);
  const double length = per_speed_ * row[2];
  from.y() += std::max(0.0, -(from.y() + length));
  return {from, from + Point(0, length)};
}

std::vector<DrawnForce> BouncingBallDiagram::forces(std::span<const double> row) const {
  // The weight beside the ball, from above its top down to the level of its
  // bottom, so that it ends on the ground, not in it, when the ball lands.
  const Point c = ball_center(row), beside = c - Point(kArrowOffset * radius_, 0);
  const double length = kWeightLength * radius_;
  std::vector<DrawnForce> out = {{ForceKind::weight, {beside + Point(0, length - radius_), beside - Point(0, radius_)},
                                  colors_.gravity, "<i>mg</i>"}};
  // At rest the ground holds it up: N = mg, up from the level of the
  // contact, beside the ball opposite mg (through the ball it would hide).
  const Point contact_level = c + Point(kArrowOffset * radius_, -radius_);
  if (at_rest(row))
    out.push_back({ForceKind::normal, {contact_level, contact_level + Point(0, length)}, colors_.wire_force,
                   "<i>N</i> = <i>mg</i>"});
  return out;
}

std::optional<ForceKey> BouncingBallDiagram::force_key() const {
  const std::vector<KeyEntry> table = {
      {ForceKind::weight, {colors_.gravity, "<i>mg</i> weight"}},
      {ForceKind::normal, {colors_.wire_force, "<i>N</i> ground, at rest"}},
  };
  return ForceKey{kWeightLength * radius_, "<i>mg</i>", "burst: impulse at impact", seen_.names(table)};
}

void BouncingBallDiagram::draw_static(render::Canvas& canvas, const render::WorldView& view) const {
  const double H = highest_ > 0 ? highest_ : 1;
  render::draw_hatched_surface(canvas, view, Point(-0.7 * H, 0), Point(0.7 * H, 0), Point(0, -1), {colors_.wire, 2.2});
}

void BouncingBallDiagram::draw(render::Canvas& canvas, const render::WorldView& view, std::span<const double> row) {
  if (ghost()) return render::draw_circle(canvas, view, ball_center(row), radius_, colors_.bob, {colors_.wire, 1.8});
  const double t = row[0], H = highest_ > 0 ? highest_ : 1;
  // Impacts so far, and the burst of the latest while it fades.
  const size_t count = std::upper_bound(impacts_.begin(), impacts_.end(), t + 1e-12) - impacts_.begin();
  if (count > 0) {
    const double age = (t - impacts_[count - 1]) / (0.2 * (period_ > 0 ? period_ : 1));
    if (age < 1) {
      // The ground's impulse, in N's colour: thinning as it fades, never faint.
      const render::Stroke burst{render::legible_on(colors_.wire_force, colors_.background), 1 + 1.6 * (1 - age)};
      for (int i = 0; i < 7; ++i) {
        const double a = M_PI * (i + 0.5) / 7;
        const Point d(std::cos(a), std::sin(a));
        render::draw_line(canvas, view, 1.25 * radius_ * d, (1.6 + 0.4 * age) * radius_ * d, burst);
      }
    }
  }
  // The tally: a dot per impact on the ground at the right, rows upward, in
  // ink (a count, not a force).
  for (size_t i = 0; i < std::min<size_t>(count, kTallyMost); ++i)
    render::draw_circle(canvas, view,
                        Point((kTallyLeft + (i % kTallyRow) * kTallySpacing) * H,
                              (kTallyDot + 0.004 + (i / kTallyRow) * kTallySpacing) * H),
                        kTallyDot * H, colors_.wire, {colors_.wire, 1});
  char tally[48];
  std::snprintf(tally, sizeof tally, "%zu impact%s", count, count == 1 ? "" : "s");
  render::TextStyle label{18, colors_.wire};
  label.halo = true, label.halo_color = colors_.background;
  const double rows = std::ceil(double(std::clamp<size_t>(count, 1, kTallyMost)) / kTallyRow);
  render::draw_text(canvas, view.to_pixel(Point((kTallyLeft - kTallyDot) * H, (rows * kTallySpacing + 0.02) * H)), tally,
                    label, render::Anchor::bottom_left);

  render::draw_circle(canvas, view, ball_center(row), radius_, colors_.bob, {colors_.wire, 1.8});
  for (const DrawnForce& f : forces(row))
    render::draw_force_arrow(canvas, view, {f.arrow.from, f.arrow.to, f.color, f.label, render::LabelPlace::beside,
                                            Point(f.kind == ForceKind::weight ? -1 : 1, 0)}, colors_.background);
  if (at_rest(row)) return;  // v = 0: no arrow beside the normal force's label
  const Arrow v = velocity_arrow(row);
  render::draw_force_arrow(canvas, view, {v.from, v.to, colors_.bob, "<i>v</i>", render::LabelPlace::beside, Point(1, 0)},
                           colors_.background);
}

DiagramKind bouncing_ball_diagram_kind() {
  return {"bouncing_ball",
          "ball bouncing on the ground: velocity and weight arrows, a burst and a tally mark at each impact "
          "(section 1.12.9)",
          {"bouncing-ball"}, [](const DiagramInput& in) {
            return std::make_unique<BouncingBallDiagram>(in.parameters.number("g"), in.info.mesh.period, in.info.exact,
                                                         in.config.colors);
          }};
}

}  // namespace vibra::scenes
