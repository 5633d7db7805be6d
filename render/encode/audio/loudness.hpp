// Loudness of a mono clip as ITU-R BS.1770 measures it (LUFS), and a gain that brings speech to a target.
#pragma once
#include "render/encode/audio/audio_clip.hpp"

namespace vibra::render {

/// Podcasts' and lecture videos' loudness: speech sits here in every shot.
inline constexpr double kSpeechLoudness = -16;  // LUFS

/// Integrated loudness in LUFS (K-weighted, 400 ms blocks every 100 ms,
/// gated at -70 LUFS and 10 LU below the ungated mean, as BS.1770-4 and
/// FFmpeg's ebur128 filter); -infinity for a silent clip.
double integrated_loudness(const AudioClip&);

/// Scales `clip` to `target` LUFS, less where its peak would pass -1 dBFS.
/// A silent clip stays as it is.
void normalize_loudness(AudioClip& clip, double target = kSpeechLoudness);

}  // namespace vibra::render
