// The pendulum's exact period 4 K(sin(Theta/2)), K by the arithmetic-geometric mean.
#pragma once

namespace vibra {

/// The complete elliptic integral of the first kind,
/// K(k) = integral_0^{pi/2} dphi / sqrt(1 - k^2 sin^2 phi), 0 <= k < 1, by the
/// arithmetic-geometric mean: K(k) = pi / (2 AGM(1, sqrt(1 - k^2))), which
/// doubles its correct digits per iteration. Infinite at k = 1.
double complete_elliptic_k(double k);

/// K from the complementary modulus k' = sqrt(1 - k^2), for k near 1 where
/// forming 1 - k^2 would lose digits.
double complete_elliptic_k_complementary(double k_prime);

/// The period of theta'' + sin(theta) = 0 (scaled time, the small-angle period
/// is 2 pi) when theta swings between -amplitude and amplitude:
/// 4 K(sin(amplitude/2)). Infinite for amplitude >= pi (the pendulum stops at
/// or goes over the top).
double pendulum_period(double amplitude);

}  // namespace vibra
