// A force arrow drawn to its run's scale, or clipped to the room its part has with a break mark across its shaft.
#pragma once
#include "render/draw/annotations.hpp"
#include "scenes/diagrams/forces/force_scale.hpp"

namespace vibra::scenes {

/// Draws `f` (world units, already to its ForceScale) as
/// render::draw_force_arrow does, clipped to `room` world units (the scale's
/// longest()); a clipped arrow gets a break mark, two slanted strokes across
/// its shaft, so it reads as longer than drawn (docs/drawing.md). Returns
/// whether it was clipped.
bool draw_broken_force(render::Canvas&, const render::WorldView&, double room, render::ForceArrow f,
                       const render::Color& background);

}  // namespace vibra::scenes
