// How far a conservative oscillator can swing: where its potential first reaches its energy.
#pragma once
#include <functional>

namespace vibra {

/// How far u can go from u0 with energy E0 = potential(u0) + kinetic: the
/// largest |u| at which `potential` first reaches E0, searched outward from
/// u0 on both sides (doubling the step, then bisecting). 0 when it does not
/// reach E0 within 1e6 steps' worth (a force that does not restore).
double potential_reach(const std::function<double(double)>& potential, double u0, double E0, double step);

}  // namespace vibra
