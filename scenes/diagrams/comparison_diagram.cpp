#include "scenes/diagrams/comparison_diagram.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace vibra::scenes {

namespace {
/// Ghosts are this opaque: the first member shows through them.
constexpr double kGhostAlpha = 0.5;
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

std::optional<WorldBox> ComparisonDiagram::view_at(std::span<const double> row) const {
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
  auto draw_member = [&](Member& m) {
    const auto member = m.columns.slice(row, slice_);
    if (std::isfinite(member[1])) m.diagram->draw(canvas, view, member);
  };
  if (members_.size() > 1) {
    // All ghosts in one group, made faint together (one layer per frame),
    // under the first run, which stays clear with its forces.
    cairo_push_group(canvas.cr());
    for (size_t i = 1; i < members_.size(); ++i) draw_member(members_[i]);
    cairo_pop_group_to_source(canvas.cr());
    cairo_paint_with_alpha(canvas.cr(), kGhostAlpha);
  }
  draw_member(members_.front());
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
