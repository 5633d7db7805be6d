// The label placer: puts each requested label where it covers nothing, and keeps it still between frames.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "render/labels/label_request.hpp"
#include "render/labels/outline.hpp"
#include "render/labels/static_marks.hpp"

namespace vibra::render {

/// Where a label sits relative to its anchor: turned from its preferred
/// direction by `turn` steps of 22.5 degrees, pushed out by `steps` steps.
struct LabelSpot {
  int turn = 0, steps = 0;
  bool operator==(const LabelSpot&) const = default;
};

/// The spots labels took in the frame before, by their text (and, for a
/// text that occurs twice, its occurrence): a label keeps its spot while that
/// is free and not much worse than the best one, so it does not flicker
/// between two spots as what surrounds it moves a pixel. The render job
/// starts it afresh every few frames, so a still replays at most those.
using LabelMemory = std::map<std::string, LabelSpot>;

/// Where a label went.
struct PlacedLabel {
  LabelRequest request;
  PixelRect box;       ///< the text with its halo, in pixels
  bool free = true;    ///< it overlaps nothing (false: no free spot in reach, the least covered one)
  bool leader = false; ///< away from its anchor: a thin line leads back
  LabelSpot spot;
};

/// Places labels one after another, each where its box (text and halo)
/// overlaps nothing in `outline` and no label placed before it, inside
/// `bounds`: its preferred spot if free, else the free spot around the
/// anchor that costs least (distance pushed out plus turn away from the
/// preferred direction). With `memory`, a label keeps the spot it had in the
/// frame before while that spot is free and costs at most a little more than
/// the best, and `memory` then holds this frame's spots. A pure function of
/// the picture and the memory, so that a frame is the still at its time when
/// the still replays the frames since the memory began. The placed boxes
/// join `outline` as labels. With `static_marks`, the outline's leading
/// static shapes are taken as marked there (the same spots, less work).
std::vector<PlacedLabel> place_labels(Canvas&, const std::vector<LabelRequest>&, Outline& outline,
                                      const PixelRect& bounds, LabelMemory* memory = nullptr,
                                      StaticMarks* static_marks = nullptr);

/// Draws placed labels with their halos, and leader lines where they moved away.
void draw_placed_labels(Canvas&, const std::vector<PlacedLabel>&);

/// A label asked for while drawing: queued on a recording canvas
/// (Canvas::record_into), placed later with everything else known; drawn at
/// its preferred spot at once on a canvas that does not record.
void request_label(Canvas&, const LabelRequest&);

}  // namespace vibra::render
