// A comparison's members in one diagram: the first drawn solid with its forces, the others as ghosts.
#include "scenes/diagrams/comparison_diagram.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "render/draw/stroke_raster.hpp"
#include "render/labels/drawing_record.hpp"

namespace vibra::scenes {

namespace {
/// Ghosts are this opaque: the first member shows through them.
constexpr double kGhostAlpha = 0.5;
/// 720p pixels of a dash in a ghost's outline.
constexpr double kGhostDash = 7;
/// 720p pixels the ghosts may move from one frame to the next and still be
/// drawn in a group the size of where they were.
constexpr double kGhostMargin = 48;

/// The filled bodies a drawing recorded (a bob, a box, a wheel's rim), as
/// polygons in pixels; small ones (a wheel's hub) are left out.
std::vector<std::vector<render::Point>> body_polygons(const render::Outline& outline, double smallest) {
  std::vector<std::vector<render::Point>> out;
  for (const render::OutlineShape& shape : outline.shapes())
    if (shape.kind == render::OutlineKind::body && shape.bounds.w >= smallest && shape.bounds.h >= smallest)
      for (const auto& polygon : shape.polygons) out.push_back(polygon);
  return out;
}

/// Ghost k of n's bodies outlined in its colour over everything, dashed so
/// that the ghosts' dashes take turns along a shared edge: runs that
/// coincide (Crank-Nicolson and RK4 at a coarse step) all show, and a ghost
/// on the first run shows over it.
void outline_ghost(render::Canvas& canvas, const std::vector<std::vector<render::Point>>& bodies, size_t k, size_t n,
                   const render::Color& color) {
  if (bodies.empty()) return;
  const double scale = canvas.scale(), dash = kGhostDash * scale;
  cairo_t* cr = canvas.cr();
  cairo_save(cr);
  cairo_new_path(cr);
  for (const auto& polygon : bodies) {
    cairo_move_to(cr, polygon.front().x(), polygon.front().y());
    for (size_t i = 1; i < polygon.size(); ++i) cairo_line_to(cr, polygon[i].x(), polygon[i].y());
    cairo_close_path(cr);
  }
  const double pattern[] = {dash, std::max<double>(1, n - 1) * dash};
  cairo_set_dash(cr, pattern, 2, -double(k) * dash);
  cairo_set_line_width(cr, 2.4 * scale);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);  // a box's corners too: the software stroke draws them
  cairo_set_source_rgba(cr, color.r, color.g, color.b, color.a);
  if (!render::raster_stroke(cr)) cairo_stroke(cr);
  cairo_restore(cr);
}

/// Paints the source at `alpha` only inside `box` (device pixels, widened to
/// whole ones): the ghosts' group is as large as the diagram's part, but
/// they cover a fraction of it, and outside what they drew it is empty.
void paint_within(cairo_t* cr, const Eigen::AlignedBox2d& box, double alpha) {
  cairo_save(cr);
  cairo_identity_matrix(cr);
  const double x0 = std::floor(box.min().x()) - 1, y0 = std::floor(box.min().y()) - 1;
  cairo_rectangle(cr, x0, y0, std::ceil(box.max().x()) + 1 - x0, std::ceil(box.max().y()) + 1 - y0);
  cairo_clip(cr);
  cairo_paint_with_alpha(cr, alpha);
  cairo_restore(cr);
}
}  // namespace

ComparisonDiagram::ComparisonDiagram(std::vector<Member> members, bool shared_exact, std::string exact_label)
    : members_(std::move(members)), shared_exact_(shared_exact), exact_label_(std::move(exact_label)) {
  size_t widest = 0;
  for (size_t i = 0; i < members_.size(); ++i) {
    widest = std::max(widest, members_[i].columns.width);
    members_[i].diagram->set_ghost(i > 0);
  }
  if (widest > kMostMemberColumns) throw std::logic_error("a comparison member has more columns than a panel reads");
  slice_.resize(widest);
}

void ComparisonDiagram::record(std::span<const double> row, WorldBox& world) {
  for (size_t k = 0; k < members_.size(); ++k) {
    const auto member = members_[k].columns.slice(row, slice_);
    if (!std::isfinite(member[1])) continue;
    // Every member's drawing sees every member's row: one geometry for all.
    for (size_t i = 0; i < members_.size(); ++i)
      if (i == k) members_[i].diagram->record(member, world);
      else members_[i].diagram->record_other(member, world);
  }
}

void ComparisonDiagram::finish_recording(WorldBox& world) {
  for (Member& m : members_) m.diagram->finish_recording(world);
}

std::optional<FollowingView> ComparisonDiagram::view_at(std::span<const double> row) const {
  // A following view follows the first member still running.
  for (const Member& m : members_) {
    const auto member = m.columns.slice(row, slice_);
    if (std::isfinite(member[1])) return m.diagram->view_at(member);
  }
  return members_.front().diagram->view_at(members_.front().columns.slice(row, slice_));
}

void ComparisonDiagram::draw_static(render::Canvas& canvas, const render::WorldView& view) const {
  members_.front().diagram->draw_static(canvas, view);
}

void ComparisonDiagram::draw(render::Canvas& canvas, const render::WorldView& view, std::span<const double> row) {
  std::vector<Bodies> ghost_bodies(members_.size());
  if (members_.size() > 1) {
    // The group under the ghosts is cleared for every frame: as large as the
    // diagram's part, that was a twentieth of a comparison frame's drawing.
    // Where they drew last frame, with a margin, is room enough unless they
    // jumped; then they are drawn again in a group of the whole part.
    std::optional<std::vector<Bodies>> drawn;
    if (!ghosts_drawn_.isEmpty()) {
      const double margin = kGhostMargin * canvas.scale();
      const Eigen::AlignedBox2d& b = ghosts_drawn_;
      drawn = draw_ghosts(canvas, view, row,
                          render::PixelRect{b.min().x() - margin, b.min().y() - margin, b.sizes().x() + 2 * margin,
                                            b.sizes().y() + 2 * margin});
    }
    if (!drawn) drawn = draw_ghosts(canvas, view, row, std::nullopt);
    ghost_bodies = std::move(*drawn);
  }
  const auto first = members_.front().columns.slice(row, slice_);
  if (std::isfinite(first[1])) members_.front().diagram->draw(canvas, view, first);
  for (size_t i = 1; i < members_.size(); ++i)
    outline_ghost(canvas, ghost_bodies[i], i - 1, members_.size() - 1, members_[i].entry.color);
}

std::optional<std::vector<ComparisonDiagram::Bodies>> ComparisonDiagram::draw_ghosts(
    render::Canvas& canvas, const render::WorldView& view, std::span<const double> row,
    const std::optional<render::PixelRect>& room) {
  // Each ghost is recorded on its own to find its bodies, then into the frame's record.
  cairo_t* cr = canvas.cr();
  render::DrawingRecord* frame = canvas.record();
  std::vector<render::DrawingRecord> ghosts(members_.size());
  Eigen::AlignedBox2d drawn;  // empty
  Eigen::AlignedBox2d* outer = canvas.extent_into(&drawn);
  cairo_save(cr);
  if (room) render::clip_to_pixels(cr, *room);
  cairo_push_group(cr);
  for (size_t i = 1; i < members_.size(); ++i) {
    canvas.record_into(&ghosts[i]);
    const auto member = members_[i].columns.slice(row, slice_);
    if (std::isfinite(member[1])) members_[i].diagram->draw(canvas, view, member);
  }
  canvas.record_into(frame);
  canvas.extent_into(outer);
  cairo_pop_group_to_source(cr);
  // paint_within takes a pixel more on each side: the room must hold that too.
  const bool fits = !room || drawn.isEmpty() ||
                    (drawn.min().x() - 2 >= room->x && drawn.min().y() - 2 >= room->y &&
                     drawn.max().x() + 2 <= room->x + room->w && drawn.max().y() + 2 <= room->y + room->h);
  if (fits && !drawn.isEmpty()) paint_within(cr, drawn, kGhostAlpha);
  cairo_set_source_rgb(cr, 0, 0, 0);  // lets the group go
  cairo_restore(cr);
  if (!fits) return std::nullopt;
  ghosts_drawn_ = drawn;
  if (outer && !drawn.isEmpty()) outer->extend(drawn);
  std::vector<Bodies> bodies(members_.size());
  for (size_t i = 1; i < members_.size(); ++i) {
    bodies[i] = body_polygons(ghosts[i].outline, 8 * canvas.scale());
    if (frame) {
      frame->outline.append(ghosts[i].outline);
      frame->labels.insert(frame->labels.end(), ghosts[i].labels.begin(), ghosts[i].labels.end());
    }
  }
  return bodies;
}

std::vector<PanelSpec> ComparisonDiagram::panels() const {
  std::vector<std::vector<PanelSpec>> specs;
  for (const Member& m : members_) specs.push_back(m.diagram->panels());
  std::vector<PanelSpec> out;
  for (size_t p = 0; p < specs.front().size(); ++p) {
    PanelSpec panel{specs.front()[p].label, {}};
    std::vector<SeriesSpec> exact;
    for (size_t i = 0; i < members_.size(); ++i) {
      if (p >= specs[i].size()) continue;
      const MemberColumns& columns = members_[i].columns;
      bool first = true;
      for (const SeriesSpec& s : specs[i][p].series) {
        if (!s.dashed && first) {
          panel.series.push_back({"", members_[i].entry.color, columns.reading(s.value)});
          first = false;
        } else if (s.dashed && (!shared_exact_ || i == 0)) {
          const render::Color color = shared_exact_ ? render::palette::ink : members_[i].entry.color;
          exact.push_back({"", color.with_alpha(0.8), columns.reading(s.value), true});
        }
      }
    }
    // The exact curves go over the members', so that a member on it is seen to be.
    for (auto& s : exact) panel.series.push_back(std::move(s));
    out.push_back(std::move(panel));
  }
  return out;
}

std::vector<LegendEntry> ComparisonDiagram::legend() const {
  std::vector<LegendEntry> entries;
  for (const Member& m : members_) entries.push_back(m.entry);
  bool exact = false;
  for (const PanelSpec& panel : members_.front().diagram->panels())
    for (const SeriesSpec& s : panel.series) exact = exact || s.dashed;
  if (exact)
    entries.push_back({exact_label_ + (shared_exact_ ? "" : " (dashed)"),
                       shared_exact_ ? render::palette::ink : render::palette::faint, true});
  return entries;
}

std::optional<ForceKey> ComparisonDiagram::force_key() const { return members_.front().diagram->force_key(); }

}  // namespace vibra::scenes
