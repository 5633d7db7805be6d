#include "scenes/lecture/title_card.hpp"

#include "render/draw/text.hpp"
#include "scenes/lecture/card_text.hpp"

namespace vibra::scenes {

namespace {
/// The style with its size lowered until `markup` fits `width` pixels across.
render::TextStyle fitted(render::Canvas& canvas, const std::string& markup, render::TextStyle style, double width) {
  const double across = render::text_size(canvas, markup, style).x();
  if (across > width) style.size *= width / across;
  return style;
}
}  // namespace

void draw_title_card(render::Canvas& canvas, const TitleCard& card) {
  canvas.clear(render::palette::paper);
  const double w = canvas.width(), h = canvas.height(), s = canvas.scale();
  render::TextStyle small{18, render::palette::faint};
  small.max_width = 0.9 * w;
  if (!card.lecture_title.empty() && card.lecture_title != card.text)
    render::draw_text(canvas, {w / 2, 0.1 * h}, card_markup(card.lecture_title, false), small);
  render::TextStyle big{46, render::palette::ink};
  render::TextStyle equation{34, render::palette::blue, "DejaVu Serif"};
  const bool both = !card.text.empty() && !card.equation.empty();
  double y = both ? 0.42 * h : 0.5 * h;
  if (!card.text.empty()) {
    const std::string markup = "<b>" + card_markup(card.text, false) + "</b>";
    const render::Point size = render::draw_text(canvas, {w / 2, y}, markup, fitted(canvas, markup, big, 0.9 * w));
    y += size.y() / 2;
  }
  if (both) {  // a rule between the title and its equation
    cairo_t* cr = canvas.cr();
    const double half = 0.18 * w, rule = y + 18 * s;
    cairo_set_source_rgb(cr, 0.72, 0.72, 0.75);
    cairo_set_line_width(cr, 1.5 * s);
    cairo_move_to(cr, w / 2 - half, rule);
    cairo_line_to(cr, w / 2 + half, rule);
    canvas.stroke();
    y = rule + 18 * s;
  }
  if (!card.equation.empty()) {
    const std::string markup = card_markup(card.equation, true);
    const render::TextStyle style = fitted(canvas, markup, equation, 0.9 * w);
    const render::Point size = render::text_size(canvas, markup, style);
    render::draw_text(canvas, {w / 2, both ? y + size.y() / 2 : y}, markup, style);
  }
}

}  // namespace vibra::scenes
