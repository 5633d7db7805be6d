// Loudness of a mono clip as ITU-R BS.1770 measures it (LUFS), and a gain that brings speech to a target.
#include "render/encode/audio/loudness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vibra::render {

namespace {
/// A biquad section, direct form I: b0 b1 b2 / 1 a1 a2.
struct Biquad {
  double b0, b1, b2, a1, a2;
  double x1 = 0, x2 = 0, y1 = 0, y2 = 0;
  double operator()(double x) {
    const double y = b0 * x + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
    x2 = x1, x1 = x, y2 = y1, y1 = y;
    return y;
  }
};

/// The K-weighting filter's two stages at 48 kHz (BS.1770-4, table 1 and 2).
std::vector<double> k_weighted_squares(const std::vector<float>& samples) {
  Biquad shelf{1.53512485958697, -2.69169618940638, 1.19839281085285, -1.69065929318241, 0.73248077421585};
  Biquad high_pass{1.0, -2.0, 1.0, -1.99004745483398, 0.99007225036621};
  std::vector<double> squares(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double y = high_pass(shelf(samples[i]));
    squares[i] = y * y;
  }
  return squares;
}

double to_lufs(double mean_square) { return -0.691 + 10 * std::log10(mean_square); }

/// Mean squares of the 400 ms gating blocks, one every 100 ms (one block for a shorter clip).
std::vector<double> block_powers(const std::vector<double>& squares) {
  const std::size_t block = AudioClip::kRate * 4 / 10, step = AudioClip::kRate / 10;
  std::vector<double> powers;
  if (squares.empty()) return powers;
  const std::size_t length = std::min(block, squares.size());
  for (std::size_t start = 0; start + length <= squares.size(); start += step) {
    double sum = 0;
    for (std::size_t i = start; i < start + length; ++i) sum += squares[i];
    powers.push_back(sum / double(length));
  }
  return powers;
}

/// The mean of the powers above `gate` LUFS (0 when none is).
double gated_mean(const std::vector<double>& powers, double gate) {
  double sum = 0;
  std::size_t count = 0;
  for (double p : powers)
    if (p > 0 && to_lufs(p) > gate) sum += p, ++count;
  return count ? sum / double(count) : 0;
}
}  // namespace

double integrated_loudness(const AudioClip& clip) {
  constexpr double kAbsoluteGate = -70, kRelativeGate = -10;  // LUFS, LU
  const std::vector<double> powers = block_powers(k_weighted_squares(clip.samples));
  const double ungated = gated_mean(powers, kAbsoluteGate);
  if (ungated <= 0) return -std::numeric_limits<double>::infinity();
  const double mean = gated_mean(powers, std::max(kAbsoluteGate, to_lufs(ungated) + kRelativeGate));
  return to_lufs(mean);
}

void normalize_loudness(AudioClip& clip, double target) {
  constexpr double kPeakCeiling = 0.891;  // -1 dBFS: room for the encoders' overshoot
  const double loudness = integrated_loudness(clip);
  if (!std::isfinite(loudness)) return;
  float peak = 0;
  for (float s : clip.samples) peak = std::max(peak, std::abs(s));
  const double gain = std::min(std::pow(10.0, (target - loudness) / 20), kPeakCeiling / peak);
  for (float& s : clip.samples) s = static_cast<float>(s * gain);
}

}  // namespace vibra::render
