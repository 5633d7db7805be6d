// DrawingRecord: the outlines a drawing leaves and the labels it asks for, kept for the label placer.
#pragma once
#include <vector>

#include "render/labels/label_placer.hpp"
#include "render/labels/label_request.hpp"
#include "render/labels/outline.hpp"

namespace vibra::render {

/// What a drawing leaves for the label placer while it is drawn: the outline
/// of everything stroked, filled or written, and the labels asked for, to be
/// placed once the whole drawing is known (Canvas::record_into).
struct DrawingRecord {
  Outline outline;
  std::vector<LabelRequest> labels;
  /// Where the labels went, once placed (their boxes are in the outline too).
  std::vector<PlacedLabel> placed;
  /// What the strokes and fills being drawn are (OutlineKindScope).
  OutlineKind kind = OutlineKind::drawing;
};

/// Marks what the kit draws inside a scope ("a spring"), on a canvas that
/// records; nothing otherwise.
class OutlineKindScope {
 public:
  OutlineKindScope(Canvas& canvas, OutlineKind kind) : record_(canvas.record()) {
    if (record_) previous_ = record_->kind, record_->kind = kind;
  }
  ~OutlineKindScope() {
    if (record_) record_->kind = previous_;
  }
  OutlineKindScope(const OutlineKindScope&) = delete;
  OutlineKindScope& operator=(const OutlineKindScope&) = delete;

 private:
  DrawingRecord* record_;
  OutlineKind previous_ = OutlineKind::drawing;
};

}  // namespace vibra::render
