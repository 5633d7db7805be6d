// Exercise 1.22's figure: measured steady amplitudes against gamma, one colour per beta.
#pragma once
#include <vector>

#include "core/analysis/resonance.hpp"
#include "render/plot/figure.hpp"

namespace vibra::scenes {

/// Exercise 1.22's figure: measured steady amplitudes against gamma, one
/// colour per beta, on a log axis, with the exact curves dashed.
render::Figure resonance_figure(const std::vector<ResonancePoint>&, int width, int height);

}  // namespace vibra::scenes
