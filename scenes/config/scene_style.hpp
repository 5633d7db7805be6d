// SceneStyle: what every scene shares: layout (fbd, fbd+plot, plot, grid), colours, plot window, time read-out.
#pragma once
#include <cmath>
#include <string>

#include "render/draw/canvas.hpp"
#include "scenes/overlays/note.hpp"
#include "scenes/panels/series_panel.hpp"

namespace vibra::scenes {

/// fbd: the diagram alone; fbd+plot: beside panels; plot: panels alone;
/// grid: a comparison's members in a panel each, on one time axis.
enum class Layout { fbd, fbd_plot, plot, grid };

/// Colours of a scene; scene files may override each (`colors.KEY`). The
/// names are the pendulum's, the roles hold for every system: `bob` is the
/// moving body, `wire` the ink of lines and text, and `gravity`,
/// `wire_force`, `drag` the first, second and third force of a diagram.
struct SceneColors {
  render::Color background = render::palette::paper;
  render::Color bob = render::palette::blue;
  render::Color wire = render::palette::ink;
  render::Color gravity = render::palette::vermillion;
  render::Color wire_force = render::palette::green;
  render::Color drag = render::palette::purple;
};

/// What every scene shares: layout, colours, the plots' window, the
/// read-out of time.
struct SceneStyle {
  Layout layout = Layout::fbd_plot;
  SceneColors colors;
  WindowMode window_mode = WindowMode::whole_run;
  double window = 0;         ///< window width in time units (window modes)
  double period = 2 * M_PI;  ///< for the read-out "t = ... (n periods)"; 0 = none
  std::string caption;       ///< a line of parameters at the bottom (Pango markup)
  std::string title;         ///< across the top (plain text with $math$); "" = none
  std::string equation;      ///< the equation of motion under the title (LaTeX subset); "" = none
  std::vector<Note> notes;   ///< callouts shown while their time lasts
};

/// Draws the time read-out ("t = 2.50 (0.40 periods)") at the top left of `area`.
void draw_readout(render::Canvas&, const render::PixelRect& area, double t, const SceneStyle&);

}  // namespace vibra::scenes
