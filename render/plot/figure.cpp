// Figure: static panels of curves stacked on one canvas, for vibra plot and vibra analyze.
#include "render/output/output_path.hpp"
#include "render/plot/figure.hpp"

#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "render/draw/elements/shapes.hpp"
#include "render/draw/text.hpp"
#include "render/output/output_error.hpp"
#include "render/output/temporary_file.hpp"

namespace vibra::render {

namespace {
constexpr double kTickFont = 15, kLabelFont = 18, kTitleFont = 21, kLegendFont = 15;

/// A panel placed on the canvas: its axes with their final ranges and its plot area.
struct Placed {
  Axis x, y;
  PixelRect area;
  bool x_tick_labels = false;  ///< lowest panel of a group sharing the x axis
  bool x_label = false;
  double y_label_bottom = 0;   ///< the y label sits on this line (above the legend row if it has one)

  Point to_pixel(double vx, double vy) const {
    return {area.x + x.fraction(vx) * area.w, area.y + (1 - y.fraction(vy)) * area.h};
  }
  bool shows(double vx, double vy) const { return x.shows(vx) && y.shows(vy); }
};

/// Data extents of a panel's series on its axes (log axes count positive values only).
struct Extents {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
};

Extents extents_of(const std::vector<std::unique_ptr<Series>>& series, const Axis& x, const Axis& y) {
  Extents e;
  for (const auto& s : series)
    s->for_each_point([&](double vx, double vy) {
      if (!x.shows(vx) || !y.shows(vy)) return;
      e.x0 = std::min(e.x0, vx), e.x1 = std::max(e.x1, vx);
      e.y0 = std::min(e.y0, vy), e.y1 = std::max(e.y1, vy);
    });
  return e;
}

int tick_target(double pixels, double spacing) { return std::clamp(static_cast<int>(pixels / spacing), 2, 10); }

/// A polyline in pixels, split where the axes cannot show a point (log of <= 0).
std::vector<std::vector<Point>> to_pixels(const Placed& p, const std::vector<Point>& line) {
  std::vector<std::vector<Point>> runs(1);
  for (const Point& q : line) {
    if (p.shows(q.x(), q.y())) {
      runs.back().push_back(p.to_pixel(q.x(), q.y()));
    } else if (!runs.back().empty()) {
      runs.emplace_back();
    }
  }
  return runs;
}

void draw_marker(Canvas& canvas, const Point& at, const Color& color) {
  cairo_t* cr = canvas.cr();
  cairo_new_path(cr);
  cairo_arc(cr, at.x(), at.y(), 4.5 * canvas.scale(), 0, 2 * M_PI);
  cairo_set_source_rgba(cr, color.r, color.g, color.b, color.a);
  canvas.fill_preserve();
  cairo_set_source_rgba(cr, palette::paper.r, palette::paper.g, palette::paper.b, 1);
  cairo_set_line_width(cr, 1.2 * canvas.scale());
  canvas.stroke();
}

void draw_frame(Canvas& canvas, const PixelRect& area) {
  cairo_t* cr = canvas.cr();
  cairo_set_dash(cr, nullptr, 0, 0);
  cairo_rectangle(cr, area.x, area.y, area.w, area.h);
  cairo_set_source_rgba(cr, palette::ink.r, palette::ink.g, palette::ink.b, 0.7);
  cairo_set_line_width(cr, 1.2 * canvas.scale());
  canvas.stroke();
}

/// How much of the panel's drawn data falls inside `box`: points sampled
/// every few pixels along every polyline.
int data_inside(const Placed& p, const std::vector<std::unique_ptr<Series>>& series, const PixelRect& box, double step) {
  int count = 0;
  auto inside = [&](const Point& q) { return q.x() >= box.x && q.x() <= box.x + box.w && q.y() >= box.y && q.y() <= box.y + box.h; };
  for (const auto& s : series)
    for (const auto& line : s->polylines())
      for (const auto& run : to_pixels(p, line))
        for (size_t i = 0; i < run.size(); ++i) {
          count += inside(run[i]);
          if (i == 0) continue;
          const double length = (run[i] - run[i - 1]).norm();
          for (double d = step; d < length; d += step) count += inside(run[i - 1] + (run[i] - run[i - 1]) * (d / length));
        }
  return count;
}

void draw_legend_sample(Canvas& canvas, const Point& a0, const Point& a1, const SeriesStyle& st) {
  if (st.line_width > 0) draw_pixel_line(canvas, a0, a1, {st.color, st.line_width, st.dashed});
  if (st.markers) draw_marker(canvas, (a0 + a1) / 2, st.color);
}

/// A panel's legend, measured. It goes in one row above the panel's top-right
/// corner beside the y label, or in a row of its own above the panel, where it
/// hides no data; only when neither is wide enough, into the corner of the
/// plot area that hides the least data.
struct Legend {
  enum class Place { none, beside_label, own_row, corner };
  std::vector<const Series*> entries;
  std::vector<Point> sizes;
  double row_width = 0, text_width = 0, row = 0;
  Place place = Place::none;
};

constexpr double kSample = 30, kSampleGap = 7, kEntrySpacing = 18;

Legend measure_legend(Canvas& canvas, const std::vector<std::unique_ptr<Series>>& series, double y_label_width,
                      double area_width) {
  Legend legend;
  const double s = canvas.scale();
  for (const auto& e : series) {
    if (e->label().empty()) continue;
    legend.entries.push_back(e.get());
    legend.sizes.push_back(text_size(canvas, e->label(), {kLegendFont, palette::ink}));
    legend.row_width += (legend.row_width > 0 ? kEntrySpacing * s : 0) + (kSample + kSampleGap) * s + legend.sizes.back().x();
    legend.text_width = std::max(legend.text_width, legend.sizes.back().x());
    legend.row = std::max(legend.row, legend.sizes.back().y());
  }
  if (legend.entries.empty()) return legend;
  if (legend.row_width <= area_width - y_label_width - 30 * s)
    legend.place = Legend::Place::beside_label;
  else if (legend.row_width <= area_width)
    legend.place = Legend::Place::own_row;
  else
    legend.place = Legend::Place::corner;
  return legend;
}

void draw_legend(Canvas& canvas, const Placed& p, const std::vector<std::unique_ptr<Series>>& series, const Legend& legend) {
  const double s = canvas.scale(), sample = kSample * s, gap = kSampleGap * s;
  const TextStyle style{kLegendFont, palette::ink};
  const PixelRect& a = p.area;
  const auto& entries = legend.entries;
  if (legend.place == Legend::Place::none) return;
  if (legend.place != Legend::Place::corner) {
    double x = a.x + a.w - legend.row_width;
    const double y = a.y - 4 * s - legend.row / 2;
    for (size_t i = 0; i < entries.size(); ++i) {
      draw_legend_sample(canvas, {x, y}, {x + sample, y}, entries[i]->style());
      draw_text(canvas, {x + sample + gap, y}, entries[i]->label(), style, Anchor::left);
      x += sample + gap + legend.sizes[i].x() + kEntrySpacing * s;
    }
    return;
  }
  const double row = legend.row + 3 * s, pad = 8 * s, inset = 8 * s;
  const double w = pad + sample + gap + legend.text_width + pad, h = 2 * pad + row * entries.size() - 3 * s;
  const PixelRect corners[] = {{a.x + a.w - inset - w, a.y + inset, w, h},
                               {a.x + inset, a.y + inset, w, h},
                               {a.x + a.w - inset - w, a.y + a.h - inset - h, w, h},
                               {a.x + inset, a.y + a.h - inset - h, w, h}};
  const PixelRect* best = &corners[0];
  int least = -1;
  for (const PixelRect& c : corners) {
    const int covered = data_inside(p, series, c, 4 * s);
    if (least < 0 || covered < least) least = covered, best = &c;
  }
  const PixelRect box = *best;
  fill_pixel_rect(canvas, box, palette::paper.with_alpha(0.88));
  cairo_t* cr = canvas.cr();
  cairo_rectangle(cr, box.x, box.y, box.w, box.h);
  cairo_set_source_rgba(cr, palette::faint.r, palette::faint.g, palette::faint.b, 1);
  cairo_set_line_width(cr, 1 * s);
  canvas.stroke();
  for (size_t i = 0; i < entries.size(); ++i) {
    const double y = box.y + pad + (i + 0.5) * row - 1.5 * s;
    draw_legend_sample(canvas, {box.x + pad, y}, {box.x + pad + sample, y}, entries[i]->style());
    draw_text(canvas, {box.x + pad + sample + gap, y}, entries[i]->label(), style, Anchor::left);
  }
}

void draw_series(Canvas& canvas, const Placed& p, const Series& series) {
  const SeriesStyle& st = series.style();
  cairo_save(canvas.cr());
  clip_to_pixels(canvas.cr(), p.area);
  // Stroked in pieces: Cairo's memory for one stroke grows with its length, and
  // a decimated run of many periods zigzags through every pixel column.
  constexpr size_t kPiece = 256;
  for (const auto& line : series.polylines())
    for (const auto& run : to_pixels(p, line)) {
      if (st.line_width > 0)
        for (size_t first = 0; first + 1 < run.size(); first += kPiece)
          draw_pixel_polyline(canvas, std::span(run).subspan(first, std::min(kPiece + 1, run.size() - first)),
                              {st.color, st.line_width, st.dashed});
      if (st.markers)
        for (const Point& q : run) draw_marker(canvas, q, st.color);
    }
  cairo_restore(canvas.cr());
}
/// A panel as the layout sees it.
struct PanelView {
  const PanelOptions& options;
  const std::vector<std::unique_ptr<Series>>& series;
};

const TextStyle kTickStyle{kTickFont, palette::ink.with_alpha(0.8)}, kLabelStyle{kLabelFont, palette::ink};

/// Axes fitted to the data, or to a fixed x range; panels sharing an x axis
/// (consecutive, same x label) share its range.
std::vector<Placed> fit_axes(const std::vector<PanelView>& panels) {
  const size_t n = panels.size();
  std::vector<Placed> placed(n);
  std::vector<Extents> data(n);
  for (size_t i = 0; i < n; ++i) {
    const PanelOptions& o = panels[i].options;
    placed[i].x = Axis(o.x_scale), placed[i].y = Axis(o.y_scale);
    placed[i].x.place_ticks_at(o.x_ticks);
    data[i] = extents_of(panels[i].series, placed[i].x, placed[i].y);
    placed[i].x_tick_labels = i + 1 == n || panels[i + 1].options.x_label != o.x_label;
    placed[i].x_label = placed[i].x_tick_labels && !o.x_label.empty();
  }
  for (size_t first = 0; first < n;) {
    size_t last = first;
    while (!placed[last].x_tick_labels) ++last;
    std::optional<std::pair<double, double>> fixed;
    double x0 = INFINITY, x1 = -INFINITY;
    for (size_t i = first; i <= last; ++i) {
      if (!fixed) fixed = panels[i].options.x_range;
      x0 = std::min(x0, data[i].x0), x1 = std::max(x1, data[i].x1);
    }
    for (size_t i = first; i <= last; ++i) {
      if (fixed)
        placed[i].x.set_range(fixed->first, fixed->second);
      else
        placed[i].x.fit(x0, x1);
      placed[i].y.fit(data[i].y0, data[i].y1);
    }
    first = last + 1;
  }
  return placed;
}

/// Sets every panel's plot area (and equal-aspect ranges); returns the legends as placed.
std::vector<Legend> arrange(Canvas& canvas, const std::vector<PanelView>& panels, const std::string& title, int width,
                            int height, std::vector<Placed>& placed) {
  const double s = canvas.scale();
  const size_t n = panels.size();
  const double tick_h = text_size(canvas, "0", kTickStyle).y(), label_h = text_size(canvas, "Ag", kLabelStyle).y();

  // Legends are placed before the margins are known: against the widest plot
  // area the y tick labels could leave.
  std::vector<Legend> legends;
  for (const PanelView& panel : panels)
    legends.push_back(measure_legend(canvas, panel.series, text_size(canvas, panel.options.y_label, kLabelStyle).x(),
                                     width - 134 * s));
  auto legend_row = [&](size_t i) { return legends[i].place == Legend::Place::own_row ? legends[i].row + 6 * s : 0; };
  auto band_below = [&](const Placed& p) {
    return (p.x_tick_labels ? tick_h + 8 * s : 4 * s) + (p.x_label ? label_h + 6 * s : 0);
  };

  // Heights: the title, then per panel its y label (and legend row), the plot
  // area, and for the lowest panel of a group the tick labels and the x label.
  const double title_h = title.empty() ? 6 * s : text_size(canvas, title, {kTitleFont, palette::ink}).y() + 14 * s;
  double fixed_h = title_h + 8 * s;
  for (size_t i = 0; i < n; ++i) fixed_h += label_h + 6 * s + legend_row(i) + band_below(placed[i]);
  const double area_h = std::max(10.0, (height - fixed_h) / n);
  double top = title_h;
  for (size_t i = 0; i < n; ++i) {
    top += label_h + 6 * s + legend_row(i);
    placed[i].area = {0, top, 0, area_h};
    placed[i].y_label_bottom = top - 4 * s - legend_row(i);
    top += area_h + band_below(placed[i]);
  }

  // Widths: one left margin for all panels (wide enough for every y tick
  // label) so the frames line up; on the right, room for half an x tick label.
  // Twice, as equal aspect changes the y ticks and so the margin.
  const std::vector<Placed> fitted = placed;
  const double right = 24 * s;
  for (int pass = 0; pass < 2; ++pass) {
    double left = 0;
    for (const Placed& p : placed)
      for (const auto& tick : p.y.ticks(tick_target(p.area.h, 32 * s)))
        left = std::max(left, text_size(canvas, tick.label, kTickStyle).x());
    left += 16 * s;
    for (size_t i = 0; i < n; ++i) {
      Placed& p = placed[i];
      p.area.x = left, p.area.w = std::max(10.0, width - left - right);
      if (!panels[i].options.equal_aspect) continue;
      // Equal aspect: widen the axis whose units are shorter on screen.
      p.x = fitted[i].x, p.y = fitted[i].y;
      const double ux = (p.x.hi() - p.x.lo()) / p.area.w, uy = (p.y.hi() - p.y.lo()) / p.area.h;
      if (ux > uy)
        p.y.widen(ux / uy);
      else
        p.x.widen(uy / ux);
    }
  }
  return legends;
}

void paint_panel(Canvas& canvas, const PanelView& panel, const Placed& p, const Legend& legend) {
  const double s = canvas.scale();
  const PixelRect& a = p.area;
  const Stroke grid{palette::grid, 1}, minor_grid{palette::grid.with_alpha(0.4), 1};
  for (const auto& t : p.y.ticks(tick_target(a.h, 32 * s))) {
    const double y = p.to_pixel(p.x.lo(), t.value).y();
    draw_pixel_line(canvas, {a.x, y}, {a.x + a.w, y}, t.label.empty() ? minor_grid : grid);
    if (!t.label.empty()) draw_text(canvas, {a.x - 6 * s, y}, t.label, kTickStyle, Anchor::right);
  }
  for (const auto& t : p.x.ticks(tick_target(a.w, 110 * s))) {
    const double x = p.to_pixel(t.value, p.y.lo()).x();
    draw_pixel_line(canvas, {x, a.y}, {x, a.y + a.h}, t.label.empty() ? minor_grid : grid);
    if (p.x_tick_labels && !t.label.empty()) draw_text(canvas, {x, a.y + a.h + 4 * s}, t.label, kTickStyle, Anchor::top);
  }
  if (p.y.scale() == AxisScale::linear && p.y.lo() < 0 && p.y.hi() > 0) {
    const double y = p.to_pixel(p.x.lo(), 0).y();
    draw_pixel_line(canvas, {a.x, y}, {a.x + a.w, y}, {palette::faint, 1.2});
  }
  for (const auto& series : panel.series) draw_series(canvas, p, *series);
  draw_frame(canvas, a);
  draw_text(canvas, {a.x, p.y_label_bottom}, panel.options.y_label, kLabelStyle, Anchor::bottom_left);
  if (p.x_label)
    draw_text(canvas, {a.x + a.w / 2, a.y + a.h + text_size(canvas, "0", kTickStyle).y() + 10 * s},
              panel.options.x_label, kLabelStyle, Anchor::top);
  draw_legend(canvas, p, panel.series, legend);
}
}  // namespace

void require_picture_extension(const std::filesystem::path& path) {
  const std::string ext = lower_extension_of(path);
  if (ext != ".png" && ext != ".svg" && ext != ".pdf")
    throw OutputError("cannot tell the picture format of '" + path.string() +
                      "': end the file name in .png, .svg or .pdf");
}

Figure::Figure(int width, int height, std::string title) : width_(width), height_(height), title_(std::move(title)) {
  // Below 240x160 the axes, ticks and labels no longer fit beside the data.
  if (width < 240 || height < 160 || width > 8192 || height > 8192)
    throw OutputError("figure size " + std::to_string(width) + "x" + std::to_string(height) +
                      " is out of range: width must be 240..8192 and height 160..8192, e.g. --size 1280x720");
}

int Figure::add_panel(PanelOptions options) {
  panels_.push_back({std::move(options), {}});
  return static_cast<int>(panels_.size()) - 1;
}

Series& Figure::add(int panel, std::unique_ptr<Series> series) {
  auto& list = panels_.at(panel).series;
  list.push_back(std::move(series));
  return *list.back();
}

Series& Figure::add_points(int panel, std::string label, SeriesStyle style) {
  return add(panel, std::make_unique<Series>(Series::Kind::points, std::move(label), style));
}

Series& Figure::add_curve(int panel, std::string label, SeriesStyle style, double x0, double x1) {
  // One cell per device pixel across the whole width: at least one per column of the plot area.
  return add(panel, std::make_unique<Series>(Series::Kind::curve, std::move(label), style, width_, x0, x1));
}

Series& Figure::add_path(int panel, std::string label, SeriesStyle style) {
  return add(panel, std::make_unique<Series>(Series::Kind::path, std::move(label), style));
}

void Figure::draw(Canvas& canvas) const {
  canvas.clear(transparent_ ? palette::paper.with_alpha(0) : palette::paper);
  if (panels_.empty()) return;
  std::vector<PanelView> views;
  for (const Panel& panel : panels_) views.push_back({panel.options, panel.series});
  std::vector<Placed> placed = fit_axes(views);
  const std::vector<Legend> legends = arrange(canvas, views, title_, width_, height_, placed);
  if (!title_.empty())
    draw_text(canvas, {width_ / 2.0, 6 * canvas.scale()}, title_, {kTitleFont, palette::ink}, Anchor::top);
  for (size_t i = 0; i < views.size(); ++i) paint_panel(canvas, views[i], placed[i], legends[i]);
}

void Figure::write(const std::filesystem::path& path) const {
  require_picture_extension(path);
  const std::string ext = lower_extension_of(path);
  TemporaryFile file(path);
  if (ext == ".png") {
    Canvas canvas = Canvas::image(width_, height_);
    draw(canvas);
    canvas.flush();
    if (cairo_surface_write_to_png(canvas.surface(), file.path().c_str()) != CAIRO_STATUS_SUCCESS)
      throw OutputError("writing '" + path.string() + "' failed (disk full? unwritable?): free space or choose another path");
  } else {
    Canvas canvas = ext == ".svg" ? Canvas::svg(file.path(), width_, height_) : Canvas::pdf(file.path(), width_, height_);
    draw(canvas);
    canvas.finish();
  }
  file.commit();
}

}  // namespace vibra::render
