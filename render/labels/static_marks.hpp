// StaticMarks: the shapes every frame of a scene begins with, marked into the label placer's grid once.
#pragma once
#include <cstddef>
#include <memory>

#include "render/labels/occupancy_grid.hpp"
#include "render/labels/outline.hpp"

namespace vibra::render {

/// The leading shapes of every frame's outline that do not move (a scene's
/// static drawing: ground, walls, legend, key), marked into a grid once and
/// copied into each frame's grid, instead of marked again segment by
/// segment. Marks are an OR of shapes, so the frame's grid is the same bits
/// either way. The owner calls reset() whenever those shapes are drawn anew;
/// a grid of another area or scale is marked afresh.
class StaticMarks {
 public:
  /// The first `shapes` shapes of every outline handed to mark_into are the static ones, from now on.
  void reset(size_t shapes);
  /// Copies the static shapes' marks into `grid` (an empty grid) and returns
  /// how many leading shapes of `outline` they are: the caller marks the rest.
  size_t mark_into(OccupancyGrid& grid, const Outline& outline);

 private:
  size_t shapes_ = 0;
  std::unique_ptr<OccupancyGrid> marked_;  ///< the static shapes alone, for the last area and scale
};

}  // namespace vibra::render
