// Labelled marks on a drawing: force arrows and dimension lines.
#pragma once
#include <string>

#include "render/draw/elements/shapes.hpp"
#include "render/draw/text.hpp"

namespace vibra::render {

/// Where a force arrow's label goes.
enum class LabelPlace {
  beyond_tip,  ///< just past the arrow head
  beside,      ///< beside the middle of the shaft, on the side of `side`
};

/// A force drawn as an arrow from `from` to `to` (world units) with a label
/// in Pango markup, placed by the label placer. An arrow shorter than its
/// head is drawn as a small ring where the force acts, labelled all the same.
struct ForceArrow {
  Point from, to;
  Color color;
  std::string label;
  LabelPlace place = LabelPlace::beyond_tip;
  Point side = Point(1, 0);  ///< pixel direction for LabelPlace::beside
  bool from_rim = false;     ///< starts at a body's rim (its casing keeps off the body)
};

/// A force arrow's shaft width, 720p pixels.
inline constexpr double kForceShaftWidth = 4.2;

/// Draws the arrow (or its ring) and asks for its haloed label (see
/// request_label). `background` is the halo colour. Returns false when the
/// arrow was too short and drawn as a ring.
bool draw_force_arrow(Canvas&, const WorldView&, const ForceArrow&, const Color& background);

/// A dimension line from `a` to `b` (world units), with end ticks across it,
/// arrow heads at both ends when there is room, and a label beside its middle
/// on the side of `side` (pixel direction). Used for a displacement from
/// equilibrium: a = equilibrium, b = the body.
void draw_dimension(Canvas&, const WorldView&, const Point& a, const Point& b, const std::string& label,
                    const Point& side, const Color& color, const Color& background);

}  // namespace vibra::render
