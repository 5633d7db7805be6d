// Figure: static panels of curves stacked on one canvas, for vibra plot and vibra analyze.
#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/plot/axis.hpp"
#include "render/plot/figure_series.hpp"

namespace vibra::render {

/// What a panel shows besides its data.
struct PanelOptions {
  std::string y_label;  ///< Pango markup, set above the panel's top-left corner
  /// Pango markup under the x axis. Consecutive panels with the same x label
  /// share their x axis: one range, tick labels only under the lowest.
  std::string x_label;
  AxisScale x_scale = AxisScale::linear, y_scale = AxisScale::linear;
  bool equal_aspect = false;  ///< one unit is as long in x as in y (a path y against x)
  std::optional<std::pair<double, double>> x_range = std::nullopt;  ///< shown exactly; otherwise fitted to the data
  /// Labelled x ticks at exactly these values (e.g. the dt values of a study)
  /// instead of automatic ones.
  std::vector<double> x_ticks = {};
};

/// A static figure: panels stacked top to bottom, each with axes, a grid,
/// curves and a legend, drawn onto a Canvas or written as PNG, SVG or PDF.
/// Streamed series (curves, paths) are decimated as they arrive, so memory
/// depends on the picture's size, not on the number of points.
class Figure {
 public:
  /// Throws OutputError unless both sides are 1..8192 pixels.
  Figure(int width, int height, std::string title = "");

  /// Adds a panel below the others; returns its index.
  int add_panel(PanelOptions);
  /// A few points, kept and drawn as given (with markers if the style asks).
  Series& add_points(int panel, std::string label, SeriesStyle);
  /// y(x) for x streaming over [x0, x1] (e.g. a time series over [0, T]).
  Series& add_curve(int panel, std::string label, SeriesStyle, double x0, double x1);
  /// A path (x(s), y(s)) of any length.
  Series& add_path(int panel, std::string label, SeriesStyle);

  int width() const { return width_; }
  int height() const { return height_; }
  /// The curves of panel `panel` (0 at the top), in the order added.
  const std::vector<std::unique_ptr<Series>>& series_of(int panel) const { return panels_.at(panel).series; }
  /// No background: PNG with alpha, SVG/PDF without the paper rectangle.
  void set_transparent(bool transparent) { transparent_ = transparent; }
  void draw(Canvas&) const;
  /// Writes PNG, SVG or PDF as the extension says (any other: OutputError
  /// naming the valid ones), under a temporary name renamed when complete.
  void write(const std::filesystem::path&) const;

 private:
  struct Panel {
    PanelOptions options;
    std::vector<std::unique_ptr<Series>> series;
  };
  Series& add(int panel, std::unique_ptr<Series>);

  int width_, height_;
  std::string title_;
  std::vector<Panel> panels_;
  bool transparent_ = false;
};

/// Throws OutputError unless `path` ends in .png, .svg or .pdf (any case).
void require_picture_extension(const std::filesystem::path& path);

}  // namespace vibra::render
