#pragma once
#include <string>

#include "render/draw/canvas.hpp"
#include "render/draw/color.hpp"

namespace vibra::scenes {

/// What an arrow's length means in a free-body diagram: one scale for every
/// arrow (except those named in `note`), shown once per diagram as a key.
struct ForceKey {
  double world_per_force = 0;  ///< world units of arrow per unit of force
  std::string unit;            ///< markup: "N", "<i>mg</i>"; "" for scaled forces
  std::string note;            ///< arrows drawn at another scale, e.g. "<i>D</i> drawn ×5"
};

/// The force the key's arrow stands for: a round number (1, 2 or 5 times a
/// power of ten) whose arrow is between about 30 and 75 pixels of 720p long
/// at `pixels_per_world`. 0 when the scale is not positive and finite.
double force_key_value(const ForceKey&, double pixels_per_world, double scale);

/// Draws the key (an arrow, "= 2 N" and the note) with its bottom-left
/// corner at `bottom_left` (pixels); returns its height (0 when nothing is drawn).
double draw_force_key(render::Canvas&, const ForceKey&, double pixels_per_world, const render::Point& bottom_left,
                      const render::Color& ink);

}  // namespace vibra::scenes
