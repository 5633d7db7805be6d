#pragma once
#include <vector>

#include "render/labels/label_request.hpp"
#include "render/labels/outline.hpp"

namespace vibra::render {

/// Where a label went.
struct PlacedLabel {
  LabelRequest request;
  PixelRect box;       ///< the text with its halo, in pixels
  bool free = true;    ///< it overlaps nothing (false: no free spot in reach, the least covered one)
  bool leader = false; ///< away from its anchor: a thin line leads back
};

/// Places labels one after another, each where its box (text and halo)
/// overlaps nothing in `outline` and no label placed before it, inside
/// `bounds`: its preferred spot if free, else the free spot around the
/// anchor that costs least (distance pushed out plus turn away from the
/// preferred direction). A pure function of the picture, so that a frame is
/// the still at its time; a label moves between frames only as its anchor
/// and what surrounds it do. The placed boxes join `outline` as labels.
std::vector<PlacedLabel> place_labels(Canvas&, const std::vector<LabelRequest>&, Outline& outline,
                                      const PixelRect& bounds);

/// Draws placed labels with their halos, and leader lines where they moved away.
void draw_placed_labels(Canvas&, const std::vector<PlacedLabel>&);

/// A label asked for while drawing: queued on a recording canvas
/// (Canvas::record_into), placed later with everything else known; drawn at
/// its preferred spot at once on a canvas that does not record.
void request_label(Canvas&, const LabelRequest&);

}  // namespace vibra::render
