#pragma once
#include <string>

#include "render/draw/text.hpp"

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
};

}  // namespace vibra::render
