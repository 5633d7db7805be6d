// A curve (x(s), y(s)) thinned on a grid as it streams in, for paths that are not functions of x (orbits, phase portraits).
#pragma once
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "render/draw/canvas.hpp"

namespace vibra::render {

/// A curve (x(s), y(s)) thinned on a grid as it streams in, for paths that
/// are not functions of x (an orbit, a phase portrait). A point is kept only
/// when it enters a new grid cell, and a step between two cells already
/// joined is not stored again, so an orbit traced a million times costs what
/// one trace costs. The grid (about `resolution` cells across the path, finer
/// than any picture's pixels) coarsens when the path grows or its segments
/// exceed a fixed budget, so memory stays bounded whatever the run.
class DecimatedPath {
 public:
  explicit DecimatedPath(int resolution = 4096);

  void add(double x, double y);
  /// The kept points as polylines (a path that retraces itself breaks into several).
  const std::vector<std::vector<Point>>& strokes() const;
  /// Smallest and largest x and y of every point added.
  const Eigen::AlignedBox2d& bounds() const { return bounds_; }
  /// Segments stored (for tests: bounded memory).
  size_t segments() const { return segments_.size(); }

 private:
  using Cell = std::uint32_t;
  Cell cell_of(const Point&) const;
  bool fits_grid(const Point&) const;
  void visit(const Point&, bool joined);
  void regrid();

  int resolution_;
  Eigen::AlignedBox2d bounds_;
  Point origin_ = Point::Zero();
  double cell_size_ = 0;  ///< 0 while the grid is not set: the first points are kept raw in strokes_[0]
  std::vector<std::vector<Point>> strokes_;
  std::unordered_set<std::uint64_t> segments_;
  Cell last_cell_ = 0;
  Point last_point_ = Point::Zero();  ///< where the path last entered a new cell
  bool started_ = false;              ///< last_cell_ and last_point_ are set
  bool stroke_open_ = false;          ///< strokes_.back() ends at last_point_
};

}  // namespace vibra::render
