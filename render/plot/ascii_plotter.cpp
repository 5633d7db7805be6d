// The classic line-by-line ASCII plotter: time runs down the page, one line per time step.
#include "render/plot/ascii_plotter.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace vibra::render {

namespace {
constexpr size_t kMaxValueText = 16;  // " %.1E" is at most " -1.8E+308", 10 characters

/// printf's " %.1E", except that NaN never shows a sign: the sign bit of a
/// NaN depends on how it was made, so printing it would make output differ
/// between machines for no reason.
size_t format_value(double y, char (&text)[32]) {
  if (std::isnan(y)) return static_cast<size_t>(std::snprintf(text, sizeof text, " NAN"));
  return static_cast<size_t>(std::snprintf(text, sizeof text, " %.1E", y));
}
}  // namespace

AsciiPlotter::AsciiPlotter(AsciiPlotterOptions options) : options_(std::move(options)) {
  const double ymin = options_.ymin, ymax = options_.ymax;
  if (!std::isfinite(ymin) || !std::isfinite(ymax))
    throw std::invalid_argument("ASCII plot: ymin and ymax must be finite numbers");
  if (!(ymin < ymax)) throw std::invalid_argument("ASCII plot: ymin must be less than ymax");
  if (!std::isfinite(ymax - ymin)) throw std::invalid_argument("ASCII plot: ymax - ymin is too large for a double");
  if (options_.width < 1) throw std::invalid_argument("ASCII plot: the width must be at least 1");
  if (options_.symbols.empty()) throw std::invalid_argument("ASCII plot: give at least one plot symbol");
  if (ymin < 0 && 0 < ymax) axis_column_ = column(0.0);
}

// The same arithmetic, in the same order, as avplotter, so lines match it
// character for character. For y in [ymin, ymax] the result is in [0, width]:
// rounding is monotonic, so (y - ymin) / (ymax - ymin) never exceeds 1.
int AsciiPlotter::column(double y) const {
  return static_cast<int>(std::round((y - options_.ymin) / (options_.ymax - options_.ymin) * options_.width));
}

std::string_view AsciiPlotter::line(std::span<const double> values) {
  const size_t columns = static_cast<size_t>(options_.width) + 1;
  line_.reserve(columns + values.size() * kMaxValueText);  // so the appends below never reallocate
  line_.assign(columns, ' ');
  const std::string& symbols = options_.symbols;
  for (size_t i = 0; i < values.size(); ++i) {
    const double y = values[i];
    if (y >= options_.ymin && y <= options_.ymax) {  // false for NaN too
      line_[static_cast<size_t>(column(y))] = symbols[i % symbols.size()];
    } else {
      char text[32];
      line_.append(text, format_value(y, text));
    }
  }
  if (axis_column_ >= 0) line_[static_cast<size_t>(axis_column_)] = '|';
  return line_;
}

}  // namespace vibra::render
