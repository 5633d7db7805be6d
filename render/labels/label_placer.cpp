// The label placer: puts each requested label where it covers nothing, and keeps it still between frames.
#include "render/labels/label_placer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>

#include "render/draw/contrast.hpp"
#include "render/draw/elements/shapes.hpp"
#include "render/labels/drawing_record.hpp"
#include "render/labels/occupancy_grid.hpp"
#include "render/output/stop_signal.hpp"
#include "render/typeset/formula_draw.hpp"

namespace vibra::render {

namespace {
constexpr int kTurns = 8;            ///< directions tried each side of the preferred one, 22.5 degrees apart
constexpr double kTurnCost = 9;      ///< 720p pixels a turn of 22.5 degrees costs, against pushing out
constexpr double kStep = 2;          ///< 720p pixels between the distances tried along a direction
constexpr double kFarthest = 180;    ///< 720p pixels a label may be pushed beyond its gap
constexpr double kLeaderAfter = 10;  ///< 720p pixels pushed out (or a turn) beyond which a leader line is drawn
/// How much more (in the cost's 720p pixels) a label's spot of the frame
/// before may cost than the best free one and still be kept: a turn and a
/// half, or ten steps out.
constexpr double kKeep = 20;

struct Candidate {
  int turn;   ///< signed, in steps of 22.5 degrees
  int steps;  ///< pushed out by steps * kStep
  double cost;
};

/// Every spot tried, cheapest first; the same for every label.
const std::vector<Candidate>& candidates() {
  static const std::vector<Candidate> all = [] {
    std::vector<Candidate> out;
    const int farthest = static_cast<int>(kFarthest / kStep);
    for (int turn = -kTurns + 1; turn <= kTurns; ++turn)
      for (int steps = 0; steps <= farthest; ++steps)
        out.push_back({turn, steps, steps * kStep + std::abs(turn) * kTurnCost});
    // Ties: the smaller turn, then counter-clockwise on screen first, so the
    // order never depends on the sort's whims.
    std::stable_sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
      if (a.cost != b.cost) return a.cost < b.cost;
      if (std::abs(a.turn) != std::abs(b.turn)) return std::abs(a.turn) < std::abs(b.turn);
      return a.turn > b.turn;
    });
    return out;
  }();
  return all;
}

PixelRect box_at(const Point& centre, const Point& size) {
  return {centre.x() - 0.5 * size.x(), centre.y() - 0.5 * size.y(), size.x(), size.y()};
}

bool within(const PixelRect& inner, const PixelRect& outer) {
  return inner.x >= outer.x && inner.y >= outer.y && inner.x + inner.w <= outer.x + outer.w &&
         inner.y + inner.h <= outer.y + outer.h;
}

Point nearest_on_box(const PixelRect& box, const Point& p) {
  return {std::clamp(p.x(), box.x, box.x + box.w), std::clamp(p.y(), box.y, box.y + box.h)};
}

/// Room between a typeset label's card edge and its content, in pixels.
double card_padding(double scale) { return 5 * scale; }

/// A label's box size: its text (or typeset content on its card) and halo.
Point label_size(Canvas& canvas, const LabelRequest& request) {
  const double scale = canvas.scale();
  if (request.typeset)
    return Point(request.typeset->width, request.typeset->height()) + Point::Constant(2 * card_padding(scale));
  return text_size(canvas, request.markup, request.style) + Point::Constant(2 * halo_reach(request.style, scale));
}

/// A typeset label: a card in the halo colour with a thin border, its content inside.
void draw_card(Canvas& canvas, const PlacedLabel& label) {
  const double scale = canvas.scale(), pad = card_padding(scale), r = 4 * scale;
  const PixelRect& b = label.box;
  const TextStyle& style = label.request.style;
  cairo_t* cr = canvas.cr();
  cairo_new_path(cr);
  cairo_arc(cr, b.x + b.w - r, b.y + r, r, -M_PI / 2, 0);
  cairo_arc(cr, b.x + b.w - r, b.y + b.h - r, r, 0, M_PI / 2);
  cairo_arc(cr, b.x + r, b.y + b.h - r, r, M_PI / 2, M_PI);
  cairo_arc(cr, b.x + r, b.y + r, r, M_PI, 3 * M_PI / 2);
  cairo_close_path(cr);
  const Color fill = style.halo_color.with_alpha(0.92 * style.halo_color.a);
  cairo_set_source_rgba(cr, fill.r, fill.g, fill.b, fill.a);
  DrawingRecord* record = canvas.record();
  canvas.record_into(nullptr);  // the box is recorded as the label's already
  canvas.fill_preserve();
  const Color edge = style.color.with_alpha(0.45);
  cairo_set_source_rgba(cr, edge.r, edge.g, edge.b, edge.a);
  cairo_set_line_width(cr, 1.2 * scale);
  canvas.stroke();
  draw_math(canvas, *label.request.typeset, {b.x + pad, b.y + pad + label.request.typeset->ascent},
            {style.color, false, style.halo_color});
  canvas.record_into(record);
}

/// An arrow from the card's edge to its anchor, ending in a dot there.
void draw_pointer(Canvas& canvas, const PlacedLabel& label) {
  const double scale = canvas.scale();
  const Point anchor = label.request.anchor;
  const Point start = nearest_on_box(label.box, anchor);
  const Point d = anchor - start;
  const double length = d.norm();
  const Color color = label.request.style.color;
  DrawingRecord* record = canvas.record();
  canvas.record_into(nullptr);
  if (length > 8 * scale) {
    const Point along = d / length, across(-along.y(), along.x());
    const Point tip = anchor - 4 * scale * along, base = tip - 9 * scale * along;
    draw_pixel_line(canvas, start, base, {color.with_alpha(0.8), 1.4});
    cairo_t* cr = canvas.cr();
    cairo_new_path(cr);
    cairo_move_to(cr, tip.x(), tip.y());
    cairo_line_to(cr, base.x() + 4 * scale * across.x(), base.y() + 4 * scale * across.y());
    cairo_line_to(cr, base.x() - 4 * scale * across.x(), base.y() - 4 * scale * across.y());
    cairo_close_path(cr);
    cairo_set_source_rgba(cr, color.r, color.g, color.b, 0.8 * color.a);
    canvas.fill();
  }
  cairo_t* cr = canvas.cr();
  cairo_new_path(cr);
  cairo_arc(cr, anchor.x(), anchor.y(), 3 * scale, 0, 2 * M_PI);
  cairo_set_source_rgba(cr, color.r, color.g, color.b, color.a);
  canvas.fill();
  canvas.record_into(record);
}
}  // namespace

std::vector<PlacedLabel> place_labels(Canvas& canvas, const std::vector<LabelRequest>& requests, Outline& outline,
                                      const PixelRect& bounds, LabelMemory* memory, StaticMarks* static_marks) {
  const double scale = canvas.scale();
  OccupancyGrid grid(bounds, 2 * scale, 1.5 * scale);
  grid.add_shapes(outline.shapes(), static_marks ? static_marks->mark_into(grid, outline) : 0);
  std::vector<PlacedLabel> placed;
  LabelMemory spots;
  std::map<std::string, int> seen;  // occurrences of each text so far
  for (const LabelRequest& request : requests) {
    throw_if_stop_requested();  // each label tries every spot against those placed: the count is the input's
    const std::string key = request.markup + "#" + std::to_string(seen[request.markup]++);
    const Point size = label_size(canvas, request);
    const double n = request.direction.norm();
    const Point preferred = n > 1e-12 ? Point(request.direction / n) : Point(1, 0);
    // Each turn's direction and reach worked out once, not for each of its
    // distances: the same numbers, as the sines and cosines were a twentieth of a frame.
    std::array<std::optional<LabelRay>, 2 * kTurns> rays;
    auto box_for = [&](const Candidate& c) {
      std::optional<LabelRay>& ray = rays.at(size_t(c.turn + kTurns - 1));
      if (!ray) {
        const double angle = c.turn * M_PI / kTurns;
        const Point d(std::cos(angle) * preferred.x() + std::sin(angle) * preferred.y(),
                      -std::sin(angle) * preferred.x() + std::cos(angle) * preferred.y());
        ray = label_ray(d, size);
      }
      return box_at(label_beyond(request.anchor, *ray, request.gap + c.steps * kStep * scale), size);
    };
    // The first free spot, cheapest first; where none is, the least covered.
    const Candidate* chosen = nullptr;
    for (const Candidate& c : candidates())
      if (const PixelRect box = box_for(c); within(box, bounds) && grid.free(box)) {
        chosen = &c;
        break;
      }
    const Candidate* least_covered = nullptr;
    long long least = -1;
    for (const Candidate& c : chosen ? std::span<const Candidate>() : std::span(candidates())) {
      const PixelRect box = box_for(c);
      if (!within(box, bounds)) continue;
      if (const long long taken = grid.taken(box); least < 0 || taken < least) least = taken, least_covered = &c;
    }
    Candidate c = chosen ? *chosen : least_covered ? *least_covered : candidates().front();
    if (memory && chosen) {
      // The spot of the frame before, if still free and not much worse.
      const auto kept = memory->find(key);
      if (kept != memory->end() && !(kept->second == LabelSpot{c.turn, c.steps})) {
        const LabelSpot& s = kept->second;
        const Candidate before{s.turn, s.steps, s.steps * kStep + std::abs(s.turn) * kTurnCost};
        const PixelRect box = box_for(before);
        if (before.cost <= c.cost + kKeep && within(box, bounds) && grid.free(box)) c = before;
      }
    }
    spots[key] = {c.turn, c.steps};
    PlacedLabel label{request, box_for(c), chosen != nullptr, false, {c.turn, c.steps}};
    label.leader = request.leader == LabelRequest::Leader::arrow ||
                   (request.leader == LabelRequest::Leader::when_moved &&
                    (c.steps * kStep > kLeaderAfter || std::abs(c.turn) * kTurnCost > kLeaderAfter));
    grid.add_box(label.box);
    outline.add_box(label.box, OutlineKind::label, request.markup);
    placed.push_back(std::move(label));
  }
  if (memory) *memory = std::move(spots);
  return placed;
}

void draw_placed_labels(Canvas& canvas, const std::vector<PlacedLabel>& labels) {
  const double scale = canvas.scale();
  for (const PlacedLabel& label : labels) {
    if (!label.leader) continue;
    if (label.request.leader == LabelRequest::Leader::arrow) {
      draw_pointer(canvas, label);
      continue;
    }
    // From just off the anchor to just short of the box, under every label.
    const Point end = nearest_on_box(label.box, label.request.anchor);
    const Point d = end - label.request.anchor;
    const double length = d.norm();
    if (length < 10 * scale) continue;
    const Point along = d / length;
    // Clear of the arrow's tip it labels by more than the tip's casing.
    const Point from = label.request.anchor + 6 * scale * along, to = end - 2 * scale * along;
    const TextStyle& style = label.request.style;
    // A haloed label's leader is a thin line of ink on a casing of its halo,
    // as in a technical drawing: it reads across a body, and is not taken
    // for a force's shaft in the force's colour.
    if (style.halo) draw_pixel_line(canvas, from, to, {style.halo_color, 1.2 + 2 * 1.6});
    draw_pixel_line(canvas, from, to, {style.halo ? legible_on(palette::ink, style.halo_color) : style.color.with_alpha(0.7), 1.2});
  }
  for (const PlacedLabel& label : labels) {
    if (label.request.typeset) draw_card(canvas, label);
    else draw_text(canvas, label.box.center(), label.request.markup, label.request.style);
  }
}

void request_label(Canvas& canvas, const LabelRequest& request) {
  if (DrawingRecord* record = canvas.record()) {
    record->labels.push_back(request);
    return;
  }
  Outline nothing;
  draw_placed_labels(canvas, place_labels(canvas, {request}, nothing, {0, 0, double(canvas.width()), double(canvas.height())}));
}

}  // namespace vibra::render
