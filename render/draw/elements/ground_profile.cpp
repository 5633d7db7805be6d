// The ground under a road profile h(x): the road's line over a hatched band, so the road reads as solid.
#include "render/draw/elements/ground_profile.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/labels/drawing_record.hpp"
#include "render/output/output_error.hpp"

namespace vibra::render {

namespace {
/// One period of a ground's fill: a tile `period` pixels square, the pale
/// `fill` crossed by hatches rising to the right (the lines u + v = k period).
/// Repeated, the hatches run on unbroken across tiles.
std::shared_ptr<cairo_surface_t> hatch_tile(int period, const Color& fill, const Stroke& hatch, double scale) {
  std::shared_ptr<cairo_surface_t> tile(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, period, period),
                                        cairo_surface_destroy);
  cairo_t* cr = cairo_create(tile.get());
  cairo_set_antialias(cr, kShapeAntialias);  // as the canvas draws
  cairo_set_source_rgba(cr, fill.r, fill.g, fill.b, fill.a);
  cairo_paint(cr);
  cairo_set_source_rgba(cr, hatch.color.r, hatch.color.g, hatch.color.b, hatch.color.a);
  cairo_set_line_width(cr, hatch.width * scale);
  for (int k = 0; k <= 2; ++k) {  // k = 0 and 2 reach the corners
    cairo_move_to(cr, -2, k * period + 2);
    cairo_line_to(cr, k * period + 2, -2);
  }
  cairo_stroke(cr);
  cairo_destroy(cr);
  cairo_surface_flush(tile.get());
  return tile;
}
}  // namespace

GroundProfile::GroundProfile(std::function<double(double)> height, double spacing, double depth, Stroke stroke)
    : height_(std::move(height)), spacing_(spacing), depth_(depth), stroke_(stroke) {}

std::vector<Point> GroundProfile::road_points(const Placement& at, double p0, double p1) const {
  // At whole multiples of the step, one beyond each side.
  const double step = std::max(spacing_, 3 / at.zoom), reach = 2 * stroke_.width * at.scale;
  const double first = std::floor((p0 - reach) / at.zoom / step), last = std::ceil((p1 + reach) / at.zoom / step);
  std::vector<Point> points;
  if (!(last - first < 1e6)) return points;
  for (double i = first; i <= last; ++i) points.emplace_back(i * step * at.zoom, at.origin_row - at.zoom * height_(i * step));
  return points;
}

void GroundProfile::paint(cairo_t* cr, const Placement& at, std::vector<Point> top, double dx, double dy) const {
  if (top.size() < 2) return;
  for (Point& p : top) p -= Point(dx, dy);
  const double reach = 2 * stroke_.width * at.scale;
  double highest = top.front().y();
  for (const Point& p : top) highest = std::min(highest, p.y());
  // The band ends below the visible part: deeper would not show.
  const double drop = std::min(depth_ * at.zoom, std::max(0.0, at.bottom - dy + reach - highest));

  // The pale band, hatched: a repeated tile whose hatches sit on road column
  // 0, so they move with the road. One fill paints it (stroking each hatch cut
  // to the band would cost Cairo many times more).
  Stroke hatch = stroke_;
  hatch.width = 0.5 * stroke_.width;
  hatch.color = stroke_.color.with_alpha(0.35);
  const int period = std::max(4, static_cast<int>(std::lround(14 * at.scale)));
  const std::shared_ptr<cairo_surface_t> tile = hatch_tile(period, stroke_.color.with_alpha(0.08), hatch, at.scale);
  cairo_pattern_t* fill = cairo_pattern_create_for_surface(tile.get());
  cairo_pattern_set_extend(fill, CAIRO_EXTEND_REPEAT);
  cairo_pattern_set_filter(fill, CAIRO_FILTER_NEAREST);
  cairo_matrix_t to_pattern;
  cairo_matrix_init_translate(&to_pattern, dx, dy);
  cairo_pattern_set_matrix(fill, &to_pattern);
  cairo_new_path(cr);
  cairo_move_to(cr, top.front().x(), top.front().y());
  for (const Point& p : top) cairo_line_to(cr, p.x(), p.y());
  for (auto p = top.rbegin(); p != top.rend(); ++p) cairo_line_to(cr, p->x(), p->y() + drop);
  cairo_close_path(cr);
  cairo_set_source(cr, fill);
  cairo_fill(cr);
  cairo_pattern_destroy(fill);

  // The road's line over it.
  cairo_save(cr);
  cairo_set_source_rgba(cr, stroke_.color.r, stroke_.color.g, stroke_.color.b, stroke_.color.a);
  cairo_set_line_width(cr, 1.4 * stroke_.width * at.scale);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_move_to(cr, top.front().x(), top.front().y());
  for (const Point& p : top) cairo_line_to(cr, p.x(), p.y());
  cairo_stroke(cr);
  cairo_restore(cr);
}

void GroundProfile::record_outline(DrawingRecord& record, const Placement& at, double x0, double x1, double column0) const {
  // Pasted from tiles, not stroked: its outline is the road down to the bottom.
  std::vector<Point> ground = road_points(at, x0 - column0, x1 - column0);
  for (Point& p : ground) p.x() += column0;
  if (ground.size() < 2) return;
  ground.emplace_back(ground.back().x(), at.bottom);
  ground.emplace_back(ground.front().x(), at.bottom);
  record.outline.add_polygon(std::move(ground), OutlineKind::ground);
}

void GroundProfile::drop_tiles_outside(long long first, long long last) const {
  for (auto it = tiles_.begin(); it != tiles_.end();) {
    if (it->first >= first - 1 && it->first <= last + 1) {
      ++it;
      continue;
    }
    if (spare_.size() < kSpareTiles) spare_.push_back(std::move(it->second.image));
    it = tiles_.erase(it);
  }
}

void GroundProfile::draw_tile(Tile& tile, const Placement& at, double p0) const {
  std::vector<Point> points = road_points(at, p0, p0 + kTileWidth);
  double highest = at.bottom;
  for (const Point& p : points) highest = std::min(highest, p.y());
  // The top rounded up to whole bands of rows, so that tiles come in few
  // heights and a tile gone out of sight can be reused: a fresh image
  // costs a page fault for every 4 KiB of it.
  const int top = static_cast<int>(std::floor(highest - 2 * stroke_.width * at.scale - 1));
  tile.top = int(at.bottom) - kTileRows * ((int(at.bottom) - top + kTileRows - 1) / kTileRows);
  const int rows = std::max(1, int(at.bottom) - tile.top);
  const auto reusable = std::find_if(spare_.begin(), spare_.end(), [&](const auto& image) {
    return cairo_image_surface_get_height(image.get()) == rows;
  });
  if (reusable != spare_.end()) {
    tile.image = std::move(*reusable);
    spare_.erase(reusable);
  } else {
    tile.image.reset(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kTileWidth, rows), cairo_surface_destroy);
  }
  cairo_t* tile_cr = cairo_create(tile.image.get());
  cairo_set_operator(tile_cr, CAIRO_OPERATOR_CLEAR);  // a reused tile starts as clear as a new one
  cairo_paint(tile_cr);
  cairo_set_operator(tile_cr, CAIRO_OPERATOR_OVER);
  cairo_set_antialias(tile_cr, kShapeAntialias);  // as the canvas draws
  paint(tile_cr, at, std::move(points), p0, tile.top);
  const bool drawn = cairo_status(tile_cr) == CAIRO_STATUS_SUCCESS;
  cairo_destroy(tile_cr);
  if (!drawn) throw OutputError("cannot draw the road: out of memory for its tiles: choose a smaller --size");
  cairo_surface_flush(tile.image.get());
}

void GroundProfile::draw(Canvas& canvas, const WorldView& view) const {
  OutlineKindScope outline_kind(canvas, OutlineKind::ground);
  cairo_t* cr = canvas.cr();
  double clip_x0, clip_y0, clip_x1, clip_y1;
  cairo_clip_extents(cr, &clip_x0, &clip_y0, &clip_x1, &clip_y1);
  if (clip_x1 <= clip_x0 || clip_y1 <= clip_y0) return;
  const Point origin = view.to_pixel(Point(0, 0));
  const double column0 = std::round(origin.x());  // canvas column of road column 0
  const Placement at{canvas.id(), view.zoom(), origin.y(), std::ceil(clip_y1), canvas.scale()};
  if (DrawingRecord* record = canvas.record()) record_outline(*record, at, clip_x0, clip_x1, column0);
  if (cairo_surface_get_type(canvas.surface()) != CAIRO_SURFACE_TYPE_IMAGE) {  // a vector still: drawn as it is
    canvas.mark_drawn(clip_x0, clip_y0, clip_x1, clip_y1);
    paint(cr, at, road_points(at, clip_x0 - column0, clip_x1 - column0), -column0, 0);
    return;
  }
  if (!(placement_ == at)) tiles_.clear(), spare_.clear(), placement_ = at;
  const auto first = static_cast<long long>(std::floor((clip_x0 - column0) / kTileWidth));
  const auto last = static_cast<long long>(std::floor((clip_x1 - column0 - 1) / kTileWidth));
  drop_tiles_outside(first, last);  // a following view does not come back to them
  for (long long k = first; k <= last; ++k) {
    const double p0 = double(k) * kTileWidth;
    Tile& tile = tiles_[k];
    if (!tile.image) draw_tile(tile, at, p0);
    const double x = column0 + p0, h = cairo_image_surface_get_height(tile.image.get());
    canvas.mark_drawn(x, tile.top, x + kTileWidth, tile.top + h);
    cairo_set_source_surface(cr, tile.image.get(), x, tile.top);
    cairo_rectangle(cr, x, tile.top, kTileWidth, h);
    cairo_fill(cr);
  }
}

}  // namespace vibra::render
