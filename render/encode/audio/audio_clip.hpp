// AudioClip: mono samples at the one rate vibra's sound tracks use (48 kHz), for speech and recorded takes.
#pragma once
#include <vector>

namespace vibra::render {

/// Mono samples in [-1, 1] at kRate per second.
struct AudioClip {
  static constexpr int kRate = 48000;  ///< Opus's own rate, and AAC's common one: no resampling when encoding
  std::vector<float> samples;
  double seconds() const { return double(samples.size()) / kRate; }
};

}  // namespace vibra::render
