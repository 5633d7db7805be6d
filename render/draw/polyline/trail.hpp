// The fading path a body leaves behind, thinned by distance and bounded in memory and time.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/draw/color.hpp"

namespace vibra::render {

/// The path a body leaves behind, stamped with time and thinned as it streams
/// in: a point is kept only `spacing` world units from the last one kept, and
/// when more than `budget` are kept the spacing doubles and every other point
/// goes, so memory stays flat over any run. Drawn, the path is simplified
/// once more for the picture's zoom: a point is dropped while the straight
/// line past it misses it by less than a quarter pixel, so a frame strokes
/// what the curve's shape on screen needs (a circle of 200 pixels takes about
/// 60 segments), the same for a thousand steps as for a million.
class Trail {
 public:
  explicit Trail(double spacing, size_t budget = size_t(1) << 16);

  /// Points must come in time order.
  void add(double t, const Point& p);
  /// The path over the last `fade` time units before `t`, fading in twenty
  /// steps from the colour at 0.8 opacity to nothing; it ends at `head` (the
  /// body's position at t) when given, else at the latest kept point before t.
  ///
  /// The steps are fixed in time: between two multiples of fade/20 every
  /// older point keeps its opacity, so on an image canvas that older part is
  /// drawn once into a layer and pasted, and only the newest stretch is
  /// stroked each frame. A frame costs the same after a hundred orbits as
  /// after one, and its pixels depend only on t, never on earlier frames.
  void draw(Canvas&, const WorldView&, double t, double fade, const Color&, double width,
            const std::optional<Point>& head = std::nullopt) const;

  struct Stamped {
    double t;
    Point p;
  };
  const std::vector<Stamped>& points() const { return points_; }
  /// The kept points with time in [from, to].
  std::vector<Point> between(double from, double to) const;
  double spacing() const { return spacing_; }
  /// The points drawn at `zoom` pixels per world unit: a subset of points(),
  /// first and last included, every dropped point within a quarter pixel of
  /// the segment drawn in its place.
  const std::vector<Stamped>& drawn_points(double zoom) const;

 private:
  double spacing_;
  size_t budget_;
  std::vector<Stamped> points_;
  size_t version_ = 0;  ///< counts changes to points_, so the drawn cache knows it is stale
  mutable std::vector<Stamped> drawn_;
  mutable double drawn_zoom_ = 0;
  mutable size_t drawn_version_ = size_t(-1);

  /// The older part of the trail as drawn for one set of fixed steps.
  struct Layer {
    std::uint64_t canvas = 0;
    size_t version = 0;
    double settled = 0, fade = 0, width = 0, zoom = 0;
    Point origin = Point::Zero();  ///< where the view puts the world's origin
    Color color;
    std::shared_ptr<cairo_surface_t> image;  ///< null: nothing to draw
    int x = 0, y = 0;                        ///< the image's top-left in the canvas
  };
  mutable Layer layer_;
};

}  // namespace vibra::render
