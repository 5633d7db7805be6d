// The title and equation of motion across the top of a frame, as on a lecture slide.
#pragma once
#include <optional>
#include <string>

#include "render/draw/canvas.hpp"
#include "render/draw/color.hpp"
#include "render/typeset/math_box.hpp"

namespace vibra::scenes {

/// The title and the equation of motion across the top of a frame, as a
/// lecture slide has them: the title (text with $math$) at the left in
/// bold, the equation typeset beside it at the right when both fit on one
/// line, else under it, left-aligned. A long title breaks between words, a
/// wide equation shrinks to the width. The band's height is taken off the
/// top of the frame; what is below lays itself out in the rest.
class FrameHeading {
 public:
  /// Measured for a frame `width` x `height`; empty texts: no band.
  /// Throws UsageError for bad LaTeX in either.
  FrameHeading(const std::string& title, const std::string& equation, int width, int height);

  bool empty() const { return !title_ && !equation_; }
  /// Pixels the band takes at the top of the frame (0 when empty).
  double height() const { return height_; }
  /// Draws the band (recorded, on a recording canvas, so labels keep off it).
  void draw(render::Canvas&, const render::Color& ink) const;

  /// Where the title and the equation are drawn, in pixels (for tests).
  std::optional<render::PixelRect> title_box() const;
  std::optional<render::PixelRect> equation_box() const;

 private:
  std::optional<render::MathBox> title_, equation_;
  render::Point title_at_, equation_at_;  ///< origins: the first baselines' left ends
  double height_ = 0;
  std::string title_text_, equation_text_;
};

}  // namespace vibra::scenes
