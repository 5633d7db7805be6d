// The ground under a road profile h(x): the road's line over a hatched band, so the road reads as solid.
#pragma once
#include <cairo.h>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/draw/elements/shapes.hpp"

namespace vibra::render {

struct DrawingRecord;

/// The ground under a road profile h(x) (world units): the road's line, and a
/// band `depth` deep under it, hatched, so the road reads as solid; drawn
/// across the visible part of the view (the clip).
///
/// Its points and hatches are fixed to the world, with the world's origin put
/// on a whole pixel column (at most half a pixel from where the view puts
/// it), so a view that follows a vehicle moves the ground under it as a whole,
/// by whole pixels. On an image canvas the ground is therefore drawn once,
/// into tiles 256 pixels wide, and pasted: a long drive draws a new tile
/// every few frames instead of the whole road every frame, and a frame's
/// pixels depend only on where the view is.
class GroundProfile {
 public:
  /// The road's line has a point every `spacing` world units, or every few
  /// pixels where that is coarser.
  GroundProfile(std::function<double(double)> height, double spacing, double depth, Stroke stroke);

  void draw(Canvas&, const WorldView&) const;

  static constexpr int kTileWidth = 256;
  static constexpr int kTileRows = 32;    ///< tile heights are whole multiples of this
  static constexpr size_t kSpareTiles = 4;  ///< tiles out of sight kept for reuse

 private:
  /// What places the ground on a canvas, but for its horizontal scroll.
  struct Placement {
    std::uint64_t canvas = 0;
    double zoom = 0, origin_row = 0, bottom = 0, scale = 0;
    bool operator==(const Placement&) const = default;
  };
  struct Tile {
    std::shared_ptr<cairo_surface_t> image;
    int top = 0;  ///< canvas row of the image's first row
  };

  /// The road's points over columns [p0, p1] (P = world x times zoom), in
  /// road columns and canvas rows.
  std::vector<Point> road_points(const Placement&, double p0, double p1) const;
  /// Draws the ground through `top` (road_points) onto `cr`, where road
  /// column P and canvas row y land at (P - dx, y - dy).
  void paint(cairo_t* cr, const Placement&, std::vector<Point> top, double dx, double dy) const;
  /// The ground's outline between canvas columns x0 and x1, for the label placer.
  void record_outline(DrawingRecord&, const Placement&, double x0, double x1, double column0) const;
  /// Tiles outside [first - 1, last + 1] go, kept for reuse while there is room.
  void drop_tiles_outside(long long first, long long last) const;
  /// Draws tile `tile` (road columns [p0, p0 + kTileWidth)) into a fresh or reused image.
  void draw_tile(Tile& tile, const Placement&, double p0) const;

  std::function<double(double)> height_;
  double spacing_, depth_;
  Stroke stroke_;
  mutable Placement placement_;
  mutable std::map<long long, Tile> tiles_;  ///< by index k: columns [k, k + 1) tile widths
  mutable std::vector<std::shared_ptr<cairo_surface_t>> spare_;  ///< tiles out of sight, for reuse
};

}  // namespace vibra::render
