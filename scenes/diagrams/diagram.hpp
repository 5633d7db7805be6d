// Diagram: the interface of every model's drawing, and the forces it draws as arrows.
#pragma once
#include <Eigen/Geometry>
#include <algorithm>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/comparison.hpp"
#include "render/draw/canvas.hpp"
#include "scenes/diagrams/forces/force_key.hpp"
#include "scenes/panels/series_panel.hpp"
#include "scenes/config/scene_style.hpp"

namespace vibra::scenes {

using WorldBox = Eigen::AlignedBox2d;
using Point = render::Point;

/// A force drawn as an arrow, in world units: from where it acts to its tip.
struct Arrow {
  Point from, to;
};

/// A run's entry in a legend: its name and colour, how to tell from a row
/// that it ended early, and why.
struct LegendEntry {
  std::string label;  ///< Pango markup
  render::Color color;
  bool dashed = false;  ///< drawn as a dashed line (an exact solution)
  /// The run's main quantity in a row: NaN once it ended (empty: never does).
  std::function<double(std::span<const double> row)> probe = {};
  /// Why it ended, asked when its rows first turn NaN (empty: it blew up).
  std::function<EarlyEnd()> early_end = {};
  /// A formula typeset under the name (a scheme's update formula); "" = none.
  std::string formula = {};
};

/// A view that follows a body: the world point at its centre and the world
/// size it shows. The size is given, not taken from a moving box's corners,
/// so that it stays the same to the last bit from frame to frame: the road's
/// tiles are drawn again whenever the view's rows move.
struct FollowingView {
  Point centre;
  Point sizes;
  WorldBox box() const { return WorldBox(centre - 0.5 * sizes, centre + 0.5 * sizes); }
};

/// Widens `world` to be symmetric about the vertical line at `x`, so that a
/// pendulum's pivot sits on the frame's centre line whichever way it swings
/// further (the view centres the world box).
inline void center_horizontally_on(WorldBox& world, double x) {
  const double half = std::max(x - world.min().x(), world.max().x() - x);
  world.extend(Point(x - half, world.min().y()));
  world.extend(Point(x + half, world.min().y()));
}

/// One plot panel beside a diagram (layout fbd+plot): a y label and its curves.
struct PanelSpec {
  std::string label;  ///< Pango markup, e.g. "<i>u</i>"
  std::vector<SeriesSpec> series;
  double least_span = 0;   ///< the y range spans at least this much (SeriesPanel::set_least_span)
  std::string empty_note;  ///< shown when the first curve has no value in the run
  std::string name;        ///< the name it was asked for by (`--panels error`), "" for a scene's own
};

/// A physical system drawn at one instant in world units (y up, equal
/// aspect): the part of a scene that knows the physics. SystemScene lays it
/// out beside its panels, fits the view and adds the time read-out. Rows are
/// the model's columns, t first.
class Diagram {
 public:
  virtual ~Diagram() = default;

  /// Pre-pass over every solver row of the run: extend `world` by what must
  /// stay in view (body, springs, arrow tips), so nothing is clipped.
  virtual void record(std::span<const double> row, WorldBox& world) = 0;
  /// Pre-pass over a row of another run drawn in the same picture (a
  /// comparison's other members): what sizes the drawing (ranges, force
  /// scales) sees it too, so every member is drawn at one geometry, but
  /// what belongs to this run alone (its trail, its impacts) does not.
  virtual void record_other(std::span<const double> row, WorldBox& world) { record(row, world); }
  /// After the pre-pass: the fixed parts (walls, floor) and any balancing of
  /// the box (e.g. symmetric about a pivot).
  virtual void finish_recording(WorldBox& world) { (void)world; }
  /// A view that follows the body (a vehicle on a long road): what to show
  /// at this row. Empty for a fixed view over the whole run.
  virtual std::optional<FollowingView> view_at(std::span<const double> row) const {
    (void)row;
    return std::nullopt;
  }
  /// Parts that never move, drawn once under every frame (fixed views only).
  virtual void draw_static(render::Canvas&, const render::WorldView&) const {}
  /// Everything that moves, at this row.
  virtual void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) = 0;
  /// The panels shown beside the diagram in layout fbd+plot, top to bottom.
  virtual std::vector<PanelSpec> panels() const = 0;
  /// What an arrow's length means (world_per_force is 0 until the pre-pass
  /// has seen the forces); none for a diagram without force arrows.
  virtual std::optional<ForceKey> force_key() const { return std::nullopt; }
  /// What names the runs drawn (a comparison's members), top to bottom; empty for one run.
  virtual std::vector<LegendEntry> legend() const { return {}; }

  /// A ghost is one of a comparison's other members, drawn faint over the
  /// first: its body only, without the arrows, labels and marks that belong
  /// to the first.
  void set_ghost(bool ghost) { ghost_ = ghost; }
  bool ghost() const { return ghost_; }

 private:
  bool ghost_ = false;
};

}  // namespace vibra::scenes
