// A lecture's title card: title, text and equation drawn on a frame.
#include "scenes/lecture/title_card.hpp"

#include <algorithm>
#include <optional>

#include "render/draw/contrast.hpp"
#include "render/typeset/formula_draw.hpp"
#include "render/typeset/formula_layout.hpp"
#include "render/typeset/formula_parser.hpp"

namespace vibra::scenes {

namespace {
// 720p pixels, scaled with the canvas as labels are.
constexpr double kLectureTitleSize = 18, kTextSize = 46, kCardEquationSize = 34;

/// Rich text set at `size`, broken onto lines `width` pixels wide, and made
/// smaller (down to a third) while it is taller than `most_height`.
render::MathBox fitted_text(render::Canvas& canvas, const std::string& text, double size, bool bold, double width,
                            double most_height) {
  const auto runs = render::parse_rich_text(text);
  render::MathBox box = render::layout_rich_text(canvas, runs, {size, "DejaVu Sans", bold}, width);
  for (double shrink = 0.85; box.height() > most_height && shrink > 0.3; shrink *= 0.85)
    box = render::layout_rich_text(canvas, runs, {size * shrink, "DejaVu Sans", bold}, width);
  return box;
}

/// A formula set at `size`, made smaller (down to a third) to fit `width`.
render::MathBox fitted_formula(render::Canvas& canvas, const std::string& source, double size, double width) {
  const render::Formula formula = render::parse_formula(source);
  render::MathBox box = render::layout_formula(canvas, formula, {size});
  if (box.width > width) box = render::layout_formula(canvas, formula, {std::max(1.0 / 3, width / box.width) * size});
  return box;
}

/// The origin that centres `box` across the canvas with its middle at height `y`.
render::Point centred(const render::Canvas& canvas, const render::MathBox& box, double y) {
  return {(canvas.width() - box.width) / 2, y - box.height() / 2 + box.ascent};
}
}  // namespace

void draw_title_card(render::Canvas& canvas, const TitleCard& card) {
  canvas.clear(render::palette::paper);
  const double w = canvas.width(), h = canvas.height(), s = canvas.scale();
  if (!card.lecture_title.empty() && card.lecture_title != card.text) {
    const render::MathBox title = fitted_text(canvas, card.lecture_title, kLectureTitleSize, false, 0.9 * w, 0.12 * h);
    render::draw_math(canvas, title, centred(canvas, title, 0.1 * h), {render::legible_on(render::palette::faint, render::palette::paper)}, card.lecture_title);
  }
  const bool both = !card.text.empty() && !card.equation.empty();
  std::optional<render::MathBox> text, equation;
  if (!card.text.empty()) text = fitted_text(canvas, card.text, kTextSize, true, 0.9 * w, (both ? 0.4 : 0.7) * h);
  if (!card.equation.empty()) equation = fitted_formula(canvas, card.equation, kCardEquationSize, 0.9 * w);
  // The text, a rule and the equation, as one block centred on the card.
  const double gap = 18 * s;
  const double block = (text ? text->height() : 0) + (equation ? equation->height() : 0) + (both ? 2 * gap : 0);
  double y = std::max(0.2 * h, (h - block) / 2);
  if (text) {
    render::draw_math(canvas, *text, centred(canvas, *text, y + text->height() / 2), {render::palette::ink}, card.text);
    y += text->height();
  }
  if (both) {  // a rule between the title and its equation
    cairo_t* cr = canvas.cr();
    const double half = 0.18 * w;
    y += gap;
    cairo_set_source_rgb(cr, 0.72, 0.72, 0.75);
    cairo_set_line_width(cr, 1.5 * s);
    cairo_move_to(cr, w / 2 - half, y);
    cairo_line_to(cr, w / 2 + half, y);
    canvas.stroke();
    y += gap;
  }
  if (equation)
    render::draw_math(canvas, *equation, centred(canvas, *equation, y + equation->height() / 2),
                      {render::palette::blue}, card.equation);
}

}  // namespace vibra::scenes
