// Text set by Pango: markup laid out, measured and drawn at an anchor, sizes in 720p pixels.
#pragma once
#include <string>

#include "render/draw/canvas.hpp"

namespace vibra::render {

/// Where the anchor point sits on the text's box.
enum class Anchor { center, left, right, top, bottom, top_left, top_right, bottom_left, bottom_right };

/// Text set by Pango, so Greek letters, subscripts (<sub>) and italics (<i>)
/// in Pango markup render properly. Sizes in 720p pixels.
struct TextStyle {
  double size = 22;
  Color color = palette::ink;
  const char* family = "DejaVu Sans";
  /// A background-coloured outline, so a label stays readable over lines.
  bool halo = false;
  Color halo_color = palette::paper;
  /// When > 0: pixels the text may take across; beyond, it ends in "…".
  double max_width = 0;
};

/// Starts loading the font configuration in the background (Pango 1.50 runs
/// fontconfig's start-up on its own thread; older ones load it here), so that
/// it overlaps the work before the first label instead of delaying it. Pango's
/// default font map is per thread: call it on the thread that draws.
void start_loading_fonts();

/// Draws Pango markup at pixel point `at`; returns its size in pixels (as text_size).
Point draw_text(Canvas&, const Point& at, const std::string& markup, const TextStyle&, Anchor = Anchor::center);
/// Pango markup without its tags and with &lt; &gt; &amp; as characters: the
/// same words for a page, file metadata or a terminal, where no markup is drawn.
std::string markup_plain_text(const std::string& markup);

/// The markup's size in pixels.
Point text_size(Canvas&, const std::string& markup, const TextStyle&);

/// How far a halo reaches beyond the glyphs' outlines, in pixels.
double halo_reach(const TextStyle&, double scale);

/// Where to centre a label of `size` pixels so that it sits just beyond
/// `tip` in direction `direction` (pixel space), `gap` pixels away.
Point label_beyond(const Point& tip, const Point& direction, const Point& size, double gap);
/// What label_beyond works out from the direction and the box's size alone:
/// the unit direction and the distance from the box's centre to its edge
/// along it, for placing one box at many gaps (the label placer's spots).
struct LabelRay {
  Point direction;
  double reach;
};
LabelRay label_ray(const Point& direction, const Point& size);
/// label_beyond(tip, direction, size, gap), the same to the bit, with ray = label_ray(direction, size).
inline Point label_beyond(const Point& tip, const LabelRay& ray, double gap) {
  return tip + (gap + ray.reach) * ray.direction;
}

}  // namespace vibra::render
