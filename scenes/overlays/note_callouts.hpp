// A render's notes as callouts: near the diagram's body, or in a panel with an arrow to its curve.
#pragma once
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/labels/label_request.hpp"
#include "render/labels/outline.hpp"
#include "render/plot/plot_panel.hpp"
#include "render/typeset/math_box.hpp"
#include "scenes/overlays/note.hpp"

namespace vibra::scenes {

/// A panel a note may point at: the names it answers to and the value its
/// first curve plots from a row.
struct NoteTarget {
  std::vector<std::string> names;
  std::function<double(std::span<const double>)> value;
  bool against_time = true;
};

/// The names a panel answers to after @: its number from 1, the name it was
/// asked for by (`--panels u`), and its label's first word in plain letters
/// ("<i>θ</i> (degrees)" answers to theta, "<i>u</i>′  velocity" to u').
std::vector<std::string> panel_names(size_t index, const std::string& given, const std::string& label_markup);

/// A render's notes: each typeset once (text with $math$ on a card), shown
/// while its time lasts. A note without @PANEL is placed by the label placer
/// near the diagram's body, after every other label; one with @PANEL is
/// placed in that panel, off its curve, with an arrow to the curve's point
/// at the note's first time (the pre-pass finds the value there, so frames
/// and stills agree).
class NoteCallouts {
 public:
  /// Throws UsageError for a note's @PANEL that names no panel of `targets`.
  NoteCallouts(const std::vector<Note>&, const std::vector<NoteTarget>& targets, int width, int height, double t_end,
               render::Color ink, render::Color card);

  bool empty() const { return notes_.empty(); }
  /// Pre-pass over the run's rows: each targeted curve's value at its note's time, and its course.
  void record(std::span<const double> row);

  /// The notes without a panel shown at time t, as label requests anchored at `anchor`.
  std::vector<render::LabelRequest> body_requests(double t, const render::Point& anchor) const;
  /// Places and draws the notes pointing at panels shown at time t, each in
  /// its panel (`panel(i)` gives panel i's plot as last drawn).
  void draw_panel_notes(render::Canvas&, double t,
                        const std::function<const render::PlotPanel*(size_t)>& panel) const;

 private:
  struct Callout {
    Note note;
    std::shared_ptr<const render::MathBox> box;
    int target = -1;  ///< the panel, or -1
    double value = 0, nearest = INFINITY;  ///< the curve's value at note.from (pre-pass)
  };
  render::LabelRequest request(const Callout&, const render::Point& anchor) const;

  std::vector<Callout> notes_;
  std::vector<NoteTarget> targets_;
  /// Each targeted panel's curve, sampled over the run (for placing its notes off it).
  std::vector<std::vector<render::Point>> courses_;
  double sample_every_ = 0;
  std::vector<double> next_sample_;
  std::vector<bool> pointed_at_;  ///< per panel: whether a note points at it (its course is kept)
  render::Color ink_, card_;
};

}  // namespace vibra::scenes
