// The title and equation of motion across the top of a frame, as on a lecture slide.
#include "scenes/overlays/frame_heading.hpp"

#include <algorithm>

#include "render/typeset/formula_draw.hpp"
#include "render/typeset/formula_layout.hpp"
#include "render/typeset/formula_parser.hpp"

namespace vibra::scenes {

namespace {
constexpr double kTitleSize = 28, kEquationSize = 22;  // 720p pixels
}

FrameHeading::FrameHeading(const std::string& title, const std::string& equation, int width, int height)
    : title_text_(title), equation_text_(equation) {
  if (title.empty() && equation.empty()) return;
  render::Canvas measure = render::Canvas::image(1, height);
  const double scale = measure.scale();
  const double margin = 16 * scale, top = 10 * scale, bottom = 8 * scale, beside = 40 * scale, under = 8 * scale;
  const double room = std::max(1.0, width - 2 * margin);
  if (!title.empty())
    title_ = render::layout_rich_text(measure, render::parse_rich_text(title), {kTitleSize, "DejaVu Sans", true}, room);
  if (!equation.empty()) {
    const render::Formula formula = render::parse_formula(equation);
    equation_ = render::layout_formula(measure, formula, {kEquationSize});
    if (equation_->width > room)  // shrink to the width, down to half size
      equation_ = render::layout_formula(measure, formula, {std::max(0.5, room / equation_->width) * kEquationSize});
  }
  if (title_ && equation_ && title_->children.size() == 1 && title_->width + beside + equation_->width <= room) {
    const double baseline = top + std::max(title_->ascent, equation_->ascent);
    title_at_ = {margin, baseline};
    equation_at_ = {width - margin - equation_->width, baseline};
    height_ = baseline + std::max(title_->descent, equation_->descent) + bottom;
    return;
  }
  double y = top;
  if (title_) {
    title_at_ = {margin, y + title_->ascent};
    y = title_at_.y() + title_->descent + under;
  }
  if (equation_) {
    equation_at_ = {margin, y + equation_->ascent};
    y = equation_at_.y() + equation_->descent;
  }
  height_ = y + bottom;
}

void FrameHeading::draw(render::Canvas& canvas, const render::Color& ink) const {
  if (title_) render::draw_math(canvas, *title_, title_at_, {ink}, title_text_);
  if (equation_) render::draw_math(canvas, *equation_, equation_at_, {ink}, equation_text_);
}

std::optional<render::PixelRect> FrameHeading::title_box() const {
  if (!title_) return std::nullopt;
  return title_->rect_at(title_at_);
}

std::optional<render::PixelRect> FrameHeading::equation_box() const {
  if (!equation_) return std::nullopt;
  return equation_->rect_at(equation_at_);
}

}  // namespace vibra::scenes
