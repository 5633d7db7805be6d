// The fading path a body leaves behind, thinned by distance and bounded in memory and time.
#include "render/draw/polyline/trail.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "render/draw/polyline/simplified_polyline.hpp"
#include "render/output/output_error.hpp"

namespace vibra::render {

namespace {
/// How far a dropped point may lie from the segment drawn in its place, in pixels.
constexpr double kTolerancePixels = 0.25;
}  // namespace

Trail::Trail(double spacing, size_t budget) : spacing_(spacing), budget_(std::max<size_t>(budget, 16)) {}

void Trail::add(double t, const Point& p) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return;
  if (!points_.empty() && (p - points_.back().p).norm() < spacing_) return;
  points_.push_back({t, p});
  ++version_;
  if (points_.size() <= budget_) return;
  // Too many: coarsen the whole path, so memory stays flat over any run.
  spacing_ *= 2;
  std::vector<Stamped> kept;
  kept.reserve(points_.size() / 2 + 1);
  for (const Stamped& s : points_)
    if (kept.empty() || (s.p - kept.back().p).norm() >= spacing_) kept.push_back(s);
  points_.swap(kept);
}

std::vector<Point> Trail::between(double from, double to) const {
  auto by_time = [](const Stamped& s, double t) { return s.t < t; };
  auto first = std::lower_bound(points_.begin(), points_.end(), from, by_time);
  auto last = std::upper_bound(points_.begin(), points_.end(), to, [](double t, const Stamped& s) { return t < s.t; });
  std::vector<Point> out;
  for (auto it = first; it < last; ++it) out.push_back(it->p);
  return out;
}

const std::vector<Trail::Stamped>& Trail::drawn_points(double zoom) const {
  if (drawn_version_ != version_ || drawn_zoom_ != zoom) {
    drawn_.clear();
    for (size_t i : simplified_polyline(points_.size(), [&](size_t k) { return points_[k].p; }, kTolerancePixels / zoom))
      drawn_.push_back(points_[i]);
    drawn_zoom_ = zoom, drawn_version_ = version_;
  }
  return drawn_;
}

namespace {
constexpr int kLevels = 20;         ///< steps of the fade
constexpr double kNewest = 0.8;     ///< the newest part's opacity

/// Strokes the polyline `pixels` on `cr` in runs of one opacity each: the
/// segment from point i to i + 1 at step `level[i]`. Runs meet with butt
/// caps: round ones would overlap at every meeting and bead the trail.
void stroke_levels(cairo_t* cr, std::span<const Point> pixels, std::span<const int> level, const Color& color,
                   double width) {
  cairo_save(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_width(cr, width);
  cairo_set_dash(cr, nullptr, 0, 0);
  for (size_t start = 0; start + 1 < pixels.size();) {
    size_t end = start + 1;
    while (end + 1 < pixels.size() && level[end] == level[start]) ++end;
    const double opacity = kNewest * (1 - double(level[start]) / kLevels);
    cairo_set_source_rgba(cr, color.r, color.g, color.b, color.a * opacity);
    cairo_move_to(cr, pixels[start].x(), pixels[start].y());
    for (size_t i = start + 1; i <= end; ++i) cairo_line_to(cr, pixels[i].x(), pixels[i].y());
    cairo_stroke(cr);
    start = end;
  }
  cairo_restore(cr);
}

/// The path from time `from` to `to` (`from` on the path even between kept
/// points), with a point put in wherever it passes a time `settled - k step`:
/// simplified, a straight stretch is one segment, and its fade would be one
/// step; cut, every segment lies within one step.
std::vector<Trail::Stamped> cut_at_steps(const std::vector<Trail::Stamped>& points, double from, double to,
                                          double settled, double step) {
  auto between = [](const Trail::Stamped& a, const Trail::Stamped& b, double t) {
    const double f = b.t > a.t ? (t - a.t) / (b.t - a.t) : 0;
    return Trail::Stamped{t, a.p + f * (b.p - a.p)};
  };
  std::vector<Trail::Stamped> out;
  auto it = std::lower_bound(points.begin(), points.end(), from,
                             [](const Trail::Stamped& s, double x) { return s.t < x; });
  if (it != points.begin() && it != points.end() && it->t > from) out.push_back(between(*(it - 1), *it, from));
  for (; it != points.end() && it->t <= to; ++it) {
    if (!out.empty()) {
      const Trail::Stamped a = out.back();
      // The step boundaries strictly between a and this point, oldest first.
      const double first = std::min(std::floor((settled - a.t) / step), double(kLevels));
      const double last = std::max(std::ceil((settled - it->t) / step), 0.0);
      for (double k = first; k >= last; --k) {
        const double boundary = settled - k * step;
        if (boundary > a.t && boundary < it->t) out.push_back(between(a, *it, boundary));
      }
    }
    out.push_back(*it);
  }
  return out;
}

/// The box `pixels` stroked `width` wide cover, in whole pixels.
DamageRect covered(std::span<const Point> pixels, double width) {
  double x0 = pixels[0].x(), y0 = pixels[0].y(), x1 = x0, y1 = y0;
  for (const Point& p : pixels)
    x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y()), x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
  const double reach = width + 1;
  return {int(std::floor(x0 - reach)), int(std::floor(y0 - reach)), int(std::ceil(x1 + reach)),
          int(std::ceil(y1 + reach))};
}

/// The older part of a trail stroked into an image covering `box`, pasted while it holds.
std::shared_ptr<cairo_surface_t> stroked_layer(const std::vector<Point>& older, const std::vector<int>& level,
                                               const Color& color, double width, const DamageRect& box) {
  std::shared_ptr<cairo_surface_t> image(
      cairo_image_surface_create(CAIRO_FORMAT_ARGB32, box.x1 - box.x0, box.y1 - box.y0), cairo_surface_destroy);
  cairo_t* cr = cairo_create(image.get());
  cairo_set_antialias(cr, kShapeAntialias);  // as the canvas draws
  cairo_translate(cr, -box.x0, -box.y0);          // whole pixels: the same rasterization
  stroke_levels(cr, older, level, color, width);
  const bool drawn = cairo_status(cr) == CAIRO_STATUS_SUCCESS;
  cairo_destroy(cr);
  if (!drawn) throw OutputError("cannot draw the trail: out of memory for its layer: choose a smaller --size");
  cairo_surface_flush(image.get());
  return image;
}

/// The newest part's pixels: the last older point, the points in (settled, t], and the head.
template <typename Iterator>
std::vector<Point> recent_pixels(const WorldView& view, Iterator first, Iterator newest, Iterator last,
                                 const std::optional<Point>& head) {
  std::vector<Point> recent;
  if (newest > first) recent.push_back(view.to_pixel((newest - 1)->p));
  for (auto it = newest; it < last; ++it) recent.push_back(view.to_pixel(it->p));
  if (head && std::isfinite(head->x()) && std::isfinite(head->y())) recent.push_back(view.to_pixel(*head));
  return recent;
}
}  // namespace

void Trail::draw(Canvas& canvas, const WorldView& view, double t, double fade, const Color& color, double width,
                 const std::optional<Point>& head) const {
  if (!(fade > 0) || !std::isfinite(t)) return;
  const std::vector<Stamped>& points = drawn_points(view.zoom());
  const double pixels_wide = width * canvas.scale();
  // The steps hold from the last multiple of fade/20 on: older points keep
  // their step until t passes the next.
  const double step = fade / kLevels, settled = step * std::floor(t / step);
  const auto first = std::lower_bound(points.begin(), points.end(), settled - fade,
                                      [](const Stamped& s, double x) { return s.t < x; });
  const auto newest = std::upper_bound(points.begin(), points.end(), settled, [](double x, const Stamped& s) { return x < s.t; });
  const auto last = std::upper_bound(newest, points.end(), t, [](double x, const Stamped& s) { return x < s.t; });

  // The older part, [settled - fade, settled]: from the layer on an image canvas.
  std::vector<Point> older;
  std::vector<int> level;
  const bool layered = cairo_surface_get_type(canvas.surface()) == CAIRO_SURFACE_TYPE_IMAGE;
  const Point origin = view.to_pixel(Point(0, 0));
  const bool layer_current = layered && layer_.canvas == canvas.id() && layer_.version == version_ &&
                             layer_.settled == settled && layer_.fade == fade && layer_.width == pixels_wide &&
                             layer_.zoom == view.zoom() && layer_.origin == origin && layer_.color == color;
  if (!layer_current) {
    const std::vector<Stamped> cut = cut_at_steps(points, settled - fade, settled, settled, step);
    for (size_t i = 0; i < cut.size(); ++i) {
      older.push_back(view.to_pixel(cut[i].p));
      const double middle = i + 1 < cut.size() ? 0.5 * (cut[i].t + cut[i + 1].t) : cut[i].t;  // of the segment from i
      level.push_back(std::clamp(int(std::floor((settled - middle) / step)), 0, kLevels - 1));
    }
    if (layered) {
      layer_ = {canvas.id(), version_, settled, fade, pixels_wide, view.zoom(), origin, color, nullptr, 0, 0};
      if (older.size() >= 2) {
        const DamageRect box = covered(older, pixels_wide);
        layer_.image = stroked_layer(older, level, color, pixels_wide, box);
        layer_.x = box.x0, layer_.y = box.y0;
      }
    }
  }
  cairo_t* cr = canvas.cr();
  if (layered && layer_.image) {
    const int w = cairo_image_surface_get_width(layer_.image.get()), h = cairo_image_surface_get_height(layer_.image.get());
    canvas.mark_drawn(layer_.x, layer_.y, layer_.x + w, layer_.y + h);
    cairo_set_source_surface(cr, layer_.image.get(), layer_.x, layer_.y);
    cairo_rectangle(cr, layer_.x, layer_.y, w, h);
    cairo_fill(cr);
  } else if (!layered && older.size() >= 2) {
    const DamageRect box = covered(older, pixels_wide);
    canvas.mark_drawn(box.x0, box.y0, box.x1, box.y1);
    stroke_levels(cr, older, level, color, pixels_wide);
  }

  // The newest part, from the last older point through (settled, t] to the
  // head, at the first step, stroked every frame.
  const std::vector<Point> recent = recent_pixels(view, first, newest, last, head);
  if (recent.size() >= 2) {
    const DamageRect box = covered(recent, pixels_wide);
    canvas.mark_drawn(box.x0, box.y0, box.x1, box.y1);
    stroke_levels(cr, recent, std::vector<int>(recent.size(), 0), color, pixels_wide);
  }
}

}  // namespace vibra::render
