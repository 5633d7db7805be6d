// A scene's frame clock: its speed, fps, pacing or one frame per step, and the chains of frames labels keep their spots in.
#pragma once
#include "core/time_mesh.hpp"
#include "scenes/config/scene_config.hpp"
#include "scenes/timing/frame_clock.hpp"

namespace vibra::scenes {

/// Labels keep their spots from frame to frame within chains of this many
/// frames (3 s at 30 fps): a still or a segment replays at most this many
/// frames before its own, with nothing rasterized, to draw what the whole
/// render draws. At each chain's start a label held in a spot that is no
/// longer its best goes to the best: over 600 frames of five scenes, chains
/// of 15 frames added 67 such jumps to the 84 that spots taken cause anyway,
/// chains of 90 add 12.
inline constexpr long long kLabelChainFrames = 90;

/// The frame clock a render of `scene` uses for a run with this mesh: its
/// speed (or one small-oscillation period in 2 s), fps, pacing, or one frame
/// per step. Throws UsageError when the pacing reaches outside the run.
FrameClock frame_clock_of(const SceneConfig& scene, const TimeMesh& mesh);

/// Simulated time per second of video outside slow motion: the scene's
/// speed, else one small-oscillation period in 2 s (1 without a period).
double steady_speed(const SceneConfig& scene, const TimeMesh& mesh);

/// Simulated time per second of video outside slow motion: the scene's
/// speed, one small-oscillation period in 2 s, or one step per frame.
double video_rate_of(const SceneConfig& scene, const TimeMesh& mesh);

}  // namespace vibra::scenes
