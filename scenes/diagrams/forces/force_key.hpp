// The forces' key: each force's colour beside its name ("mg gravity").
#pragma once
#include <string>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/draw/color.hpp"

namespace vibra::scenes {

/// One force's colour and what it is, for the key's names: "<i>mg</i> gravity".
struct ForceName {
  render::Color color;
  std::string name;  ///< markup: the arrow's label, then the force's name
};

/// What an arrow means in a free-body diagram: which force each colour is,
/// and one scale for every arrow's length (except those named in `note`),
/// shown once per diagram as a key.
struct ForceKey {
  double world_per_force = 0;  ///< world units of arrow per unit of force
  std::string unit;            ///< markup: "N", "<i>mg</i>"; "" for scaled forces
  std::string note;            ///< arrows drawn at another scale, e.g. "<i>D</i> drawn ×5"
  std::vector<ForceName> names = {};  ///< the forces drawn, in their arrows' colours
};

/// The force the key's arrow stands for: a round number (1, 2 or 5 times a
/// power of ten) whose arrow is between about 30 and 75 pixels of 720p long
/// at `pixels_per_world`. 0 when the scale is not positive and finite.
double force_key_value(const ForceKey&, double pixels_per_world, double scale);

/// Whether the note fits on the scale's line within `width` pixels at this
/// zoom, with room for the longest arrow (true without a note). Where it
/// does not (a 640x360 frame beside energy bars), it takes a row of its own.
bool force_note_fits(render::Canvas&, const ForceKey&, double pixels_per_world, double width);

/// The height of the key's rows above its scale's line, at the canvas's
/// scale: the names (coloured arrows and names, in as many rows as `width`
/// pixels need) and the note's own row with `note_row`; 0 without either.
double force_key_rows_height(render::Canvas&, const ForceKey&, double width, bool note_row);

/// Draws the key with its bottom-left corner at `bottom_left` (pixels): the
/// names in rows within `width`, then a line with the scale's arrow, "= 2 N"
/// and the note (with `note_row`, on a row of its own above that line).
/// Returns its height (0 when nothing is drawn).
double draw_force_key(render::Canvas&, const ForceKey&, double pixels_per_world, const render::Point& bottom_left,
                      double width, bool note_row, const render::Color& ink);

}  // namespace vibra::scenes
