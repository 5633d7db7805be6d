// LabelRequest: a label a drawing asks for, its text and the anchor it belongs to.
#pragma once
#include <memory>
#include <string>

#include "render/draw/text.hpp"
#include "render/typeset/math_box.hpp"

namespace vibra::render {

/// A label a drawing asks for: what it says and what it belongs to. The
/// placer puts it `gap` pixels beyond `anchor` in `direction` when that spot
/// is free, else at the nearest free spot around the anchor, with a leader
/// line back to the anchor when it had to move away.
struct LabelRequest {
  std::string markup;
  TextStyle style;
  Point anchor;                 ///< pixels: an arrow's tip, a shaft's middle, a dimension's middle
  Point direction = Point(1, 0);  ///< pixels (y down), from the anchor
  double gap = 5;               ///< pixels between the anchor and the label's box
  /// Typeset content (a note with $math$) instead of `markup`: its box sets
  /// the label's size, and it is drawn in style.color on a card of
  /// style.halo_color (with a halo when style.halo).
  std::shared_ptr<const MathBox> typeset = nullptr;
  /// A leader line back to the anchor: when the label moved away (the
  /// default), always (an arrow, for a note pointing at a curve), or never.
  enum class Leader { when_moved, arrow, none } leader = Leader::when_moved;
};

}  // namespace vibra::render
