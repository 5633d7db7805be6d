// The legend of a comparison's runs, in a column of its own at the right of the diagram.
#pragma once
#include <optional>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/typeset/math_box.hpp"
#include "scenes/diagrams/diagram.hpp"

namespace vibra::scenes {

/// The legend of a comparison's runs: a column of its own at the right of
/// the diagram's area, so it never covers the drawing or a curve. Each run's
/// line and name; under a run that ended early, "left the view at t = ..."
/// or "blew up at t = ..." appears once the frame's time reaches it. An
/// entry with a formula (a scheme's update formula) has it typeset under
/// its name.
class RunLegend {
 public:
  /// Measures the entries at the frame height `height` (720p sizes, scaled).
  RunLegend(std::vector<LegendEntry>, int height);

  bool empty() const { return entries_.empty(); }
  /// The column's width in pixels.
  double width() const { return width_; }
  /// The column's height in pixels at `scale` (known after the pre-pass:
  /// a run that ends early has a row for its note).
  double height(double scale) const { return row_top(entries_.size(), scale); }
  /// Leaves the formulas out (a frame too small for them beside the
  /// drawing: the legend would cover it); the names stay.
  void drop_formulas();
  /// Pre-pass over the run's rows: when each run blows up.
  void record(std::span<const double> row);
  /// The time run i ended early, or infinity.
  double blow_up_time(size_t i) const { return blow_up_times_.at(i); }
  /// Why run i ended early.
  EarlyEnd early_end(size_t i) const { return ends_.at(i); }

  /// The lines and names, in the column whose top right corner is `corner`.
  void draw_static(render::Canvas&, const render::Point& corner) const;
  /// The blow-up notes due at time t.
  void draw(render::Canvas&, const render::Point& corner, double t) const;

 private:
  /// Where entry i's row starts below the corner.
  double row_top(size_t i, double scale) const;

  std::vector<LegendEntry> entries_;
  std::vector<std::optional<render::MathBox>> formulas_;
  std::vector<double> blow_up_times_;
  std::vector<EarlyEnd> ends_;
  double width_ = 0;
  double names_width_ = 0;  ///< the width without the formulas
};

}  // namespace vibra::scenes
