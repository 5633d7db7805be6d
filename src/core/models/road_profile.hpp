// RoadProfile (section 1.12.8): a road as heights every dx, with h(x) and h''(x).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace vibra {

/// A road as heights h_i = h(i dx), i = 0..N-1 (section 1.12.8): h(x) by
/// linear interpolation, and h''(x) from the central differences
/// (h_{i+1} - 2 h_i + h_{i-1}) / dx^2 at the nodes (q_0 = q_1 and
/// q_{N-1} = q_{N-2} at the ends), linearly interpolated.
class RoadProfile {
 public:
  /// Throws UsageError for fewer than 3 heights or dx <= 0.
  RoadProfile(std::vector<double> heights, double dx);

  /// One height per line; blank lines and lines starting with # are skipped.
  /// Throws UsageError naming the file and line of a non-number, or an empty file.
  static RoadProfile from_file(const std::string& path, double dx);
  /// A sin(2 pi x / wavelength) sampled every dx over [0, length].
  static RoadProfile sine(double A, double wavelength, double length, double dx);
  /// Smooth bumps (raised cosines) of random heights up to A and widths of
  /// 0.2 to 0.5 wavelengths, about one per wavelength, from a seeded
  /// generator: the same seed gives the same road on every machine.
  static RoadProfile bumps(double A, double wavelength, double length, double dx, std::uint64_t seed);

  double length() const { return dx_ * double(h_.size() - 1); }
  double dx() const { return dx_; }
  double height(double x) const;
  double curvature(double x) const;  ///< h''(x)
  const std::vector<double>& heights() const { return h_; }

 private:
  double interpolate(const std::vector<double>& values, double x) const;
  std::vector<double> h_, q_;
  double dx_;
};

}  // namespace vibra
