// A comparison's members in one diagram: the first drawn solid with its forces, the others as ghosts.
#pragma once
#include <memory>
#include <vector>

#include "scenes/diagrams/diagram.hpp"
#include "scenes/overlays/member_columns.hpp"

namespace vibra::scenes {

/// The members of a comparison in one diagram: the first drawn solid with its
/// forces, the others as ghosts (their bodies only, in their own colours,
/// faint, under the first, so that the first stays clear). Each
/// member's diagram reads its own columns of the comparison's rows. A member
/// whose columns turn NaN (it blew up) is drawn no more.
class ComparisonDiagram final : public Diagram {
 public:
  struct Member {
    std::unique_ptr<Diagram> diagram;
    MemberColumns columns;
    LegendEntry entry;
  };
  /// `shared_exact`: the members solve one problem, so the first member's
  /// exact solution stands for all; otherwise each has its own.
  ComparisonDiagram(std::vector<Member>, bool shared_exact, std::string exact_label);

  void record(std::span<const double> row, WorldBox&) override;
  void finish_recording(WorldBox&) override;
  std::optional<FollowingView> view_at(std::span<const double> row) const override;
  void draw_static(render::Canvas&, const render::WorldView&) const override;
  void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) override;
  /// Each panel of the first member's diagram, with one curve per member in
  /// its colour (the first curve of that panel), and the exact solution dashed.
  std::vector<PanelSpec> panels() const override;
  std::vector<LegendEntry> legend() const override;
  std::optional<ForceKey> force_key() const override;

 private:
  using Bodies = std::vector<std::vector<render::Point>>;
  /// Draws every member but the first into one group, made faint together,
  /// and returns each one's bodies; with `room`, the group covers only that
  /// much of the canvas, and when the ghosts reach beyond it nothing is
  /// drawn or recorded and the result is empty.
  std::optional<std::vector<Bodies>> draw_ghosts(render::Canvas&, const render::WorldView&, std::span<const double> row,
                                                 const std::optional<render::PixelRect>& room);

  std::vector<Member> members_;
  /// Where the ghosts drew in the frame before (pixels; empty: unknown): the
  /// next frame's group need not be larger than this with a margin. Only the
  /// group's size depends on it, never a pixel.
  Eigen::AlignedBox2d ghosts_drawn_;
  bool shared_exact_;
  std::string exact_label_;
  mutable std::vector<double> slice_;
};

}  // namespace vibra::scenes
