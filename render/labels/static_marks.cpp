// StaticMarks: the shapes every frame of a scene begins with, marked into the label placer's grid once.
#include "render/labels/static_marks.hpp"

namespace vibra::render {

void StaticMarks::reset(size_t shapes) {
  shapes_ = shapes;
  marked_.reset();
}

size_t StaticMarks::mark_into(OccupancyGrid& grid, const Outline& outline) {
  const auto& shapes = outline.shapes();
  if (shapes_ == 0 || shapes.size() < shapes_) return 0;
  if (!marked_ || !marked_->same_cells(grid)) {
    marked_ = grid.empty_like();
    for (size_t i = 0; i < shapes_; ++i) marked_->add(shapes[i]);
  }
  grid.copy_marks(*marked_);
  return shapes_;
}

}  // namespace vibra::render
