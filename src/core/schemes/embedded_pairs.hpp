// Butcher tableaus of the embedded Runge-Kutta pairs (Fehlberg 4(5), Dormand-Prince 5(4)).
#pragma once
#include <array>

namespace vibra {

/// Butcher tableaus of the embedded Runge-Kutta pairs: `b` advances the
/// solution, `e` = b - b_hat gives the local error estimate, `order` is the
/// order of the pair's lower member (the step controller's exponent is
/// 1/(order + 1)).

/// Runge-Kutta-Fehlberg 4(5): six stages, a 4th- and a 5th-order solution.
/// The 5th-order one is kept (local extrapolation, as GSL's rkf45 does), so
/// that the global error follows the tolerance as dopri5's does; their
/// difference, the 4th-order solution's error, controls the step.
struct Fehlberg45 {
  static constexpr const char* name = "rkf45";
  static constexpr int stages = 6;
  static constexpr int order = 4;
  static constexpr bool first_same_as_last = false;
  static constexpr bool dense = false;
  static constexpr std::array<double, stages> c = {0, 1.0 / 4, 3.0 / 8, 12.0 / 13, 1, 1.0 / 2};
  static constexpr std::array<std::array<double, stages>, stages> a = {{
      {},
      {1.0 / 4},
      {3.0 / 32, 9.0 / 32},
      {1932.0 / 2197, -7200.0 / 2197, 7296.0 / 2197},
      {439.0 / 216, -8, 3680.0 / 513, -845.0 / 4104},
      {-8.0 / 27, 2, -3544.0 / 2565, 1859.0 / 4104, -11.0 / 40},
  }};
  static constexpr std::array<double, stages> b = {16.0 / 135, 0, 6656.0 / 12825, 28561.0 / 56430, -9.0 / 50,
                                                   2.0 / 55};
  /// 5th minus 4th order weights (25/216, 0, 1408/2565, 2197/4104, -1/5, 0).
  static constexpr std::array<double, stages> e = {16.0 / 135 - 25.0 / 216, 0, 6656.0 / 12825 - 1408.0 / 2565,
                                                   28561.0 / 56430 - 2197.0 / 4104, -9.0 / 50 + 1.0 / 5, 2.0 / 55};
};

/// Dormand-Prince 5(4) (Hairer, Norsett and Wanner's DOPRI5, SciPy's RK45):
/// the 5th-order solution is kept; its last stage is the next step's first
/// (FSAL), and a 4th-order continuous extension gives the dense output.
struct DormandPrince54 {
  static constexpr const char* name = "dopri5";
  static constexpr int stages = 7;
  static constexpr int order = 4;
  static constexpr bool first_same_as_last = true;
  static constexpr bool dense = true;
  static constexpr std::array<double, stages> c = {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1};
  static constexpr std::array<std::array<double, stages>, stages> a = {{
      {},
      {1.0 / 5},
      {3.0 / 40, 9.0 / 40},
      {44.0 / 45, -56.0 / 15, 32.0 / 9},
      {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
      {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
      {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84},
  }};
  static constexpr std::array<double, stages> b = {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784,
                                                   11.0 / 84, 0};
  static constexpr std::array<double, stages> e = {71.0 / 57600, 0, -71.0 / 16695, 71.0 / 1920,
                                                   -17253.0 / 339200, 22.0 / 525, -1.0 / 40};
  /// The dense output's 5th coefficient (Hairer's CONTD5).
  static constexpr std::array<double, stages> d = {-12715105075.0 / 11282082432, 0, 87487479700.0 / 32700410799,
                                                   -10690763975.0 / 1880347072, 701980252875.0 / 199316789632,
                                                   -1453857185.0 / 822651844, 69997945.0 / 29380423};
};

}  // namespace vibra
