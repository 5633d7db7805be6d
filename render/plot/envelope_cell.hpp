// EnvelopeCell: what a curve did inside one pixel column (first, last, smallest and largest sample).
#pragma once
#include <cmath>

namespace vibra::render {

/// What a curve did inside one pixel column: its first and last sample and
/// its smallest and largest value, each with the x where it happened. Drawn
/// through those points in time order, a column costs at most four points
/// whatever the number of samples in it; no peak is lost, and a steep curve
/// stays a slope instead of a staircase of vertical strokes.
struct EnvelopeCell {
  struct Sample {
    double x = 0, y = 0;
  };
  bool used = false;
  bool min_first = true;  ///< the smallest value came no later than the largest
  Sample first, last, min, max;

  void add(double x, double y) {
    if (!used) {
      used = true;
      min_first = true;
      first = last = min = max = {x, y};
      return;
    }
    last = {x, y};
    if (y < min.y) min = {x, y}, min_first = false;
    if (y > max.y) max = {x, y}, min_first = true;
  }

  /// Folds in a cell whose samples all came later (a neighbouring column).
  void merge_later(const EnvelopeCell& later) {
    if (!later.used) return;
    if (!used) {
      *this = later;
      return;
    }
    last = later.last;
    const bool new_min = later.min.y < min.y, new_max = later.max.y > max.y;
    if (new_min) min = later.min, min_first = false;
    if (new_max) max = later.max, min_first = true;
    if (new_min && new_max) min_first = later.min_first;  // both new: their own order
  }

  /// Calls visit(x, y) for the column's points in time order: first, the
  /// extremes, last; each sample once.
  template <class Visit>
  void visit_in_order(Visit&& visit) const {
    if (!used) return;
    const Sample* order[] = {&first, min_first ? &min : &max, min_first ? &max : &min, &last};
    const Sample* previous = nullptr;
    for (const Sample* s : order) {
      if (previous && s->x == previous->x && s->y == previous->y) continue;
      if (s != &last && s->x == last.x && s->y == last.y) continue;  // the last sample is an extreme: visit it last
      visit(s->x, s->y);
      previous = s;
    }
  }
};

}  // namespace vibra::render
