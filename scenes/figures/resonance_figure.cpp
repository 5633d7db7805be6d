// Exercise 1.22's figure: measured steady amplitudes against gamma, one colour per beta.
#include "scenes/figures/resonance_figure.hpp"

#include <algorithm>
#include <cstdio>

#include "core/models/model.hpp"

namespace vibra::scenes {

render::Figure resonance_figure(const std::vector<ResonancePoint>& points, int width, int height) {
  render::Figure figure(width, height,
                        "Steady amplitude of <i>u</i>'' + <i>βu</i>' + <i>u</i> = sin(<i>γt</i>): measured (dots), "
                        "exact (dashed)");
  render::PanelOptions options{"amplitude (static deflections)", "<i>γ</i> (forcing / natural frequency)",
                               render::AxisScale::linear, render::AxisScale::logarithmic};
  const int panel = figure.add_panel(options);
  std::vector<double> betas;
  double gamma_max = 0;
  for (const auto& p : points) {
    if (std::find(betas.begin(), betas.end(), p.beta) == betas.end()) betas.push_back(p.beta);
    gamma_max = std::max(gamma_max, p.gamma);
  }
  using namespace render::palette;
  const render::Color colors[] = {blue, vermillion, green, purple, orange, sky};
  for (size_t k = 0; k < betas.size(); ++k) {
    const double beta = betas[k];
    char label[64];
    std::snprintf(label, sizeof label, "<i>β</i> = %g", beta);
    const render::Color color = colors[k % 6];
    render::Series& exact = figure.add_curve(panel, "", {color.with_alpha(0.8), 1.6, true, false}, 0, 1.1 * gamma_max);
    for (int i = 0; i <= 2000; ++i) {
      const double gamma = 1.1 * gamma_max * i / 2000;
      exact.add(gamma, steady_amplitude(beta, gamma));
    }
    render::Series& measured = figure.add_points(panel, label, {color, 0, false, true});
    for (const auto& p : points)
      if (p.beta == beta) measured.add(p.gamma, p.amplitude);
  }
  return figure;
}

}  // namespace vibra::scenes
