// --segment K/N, or auto from a Slurm or Kubernetes job array: which segment of a render this process draws.
#pragma once
#include <functional>
#include <string>

#include "render/encode/join/frame_segment.hpp"

namespace vibra::cli {

/// Reads a variable of the environment; nullptr when it is not set.
using EnvironmentLookup = std::function<const char*(const char* name)>;

/// The segment `--segment TEXT` names (index and count; the total is the
/// render's): "K/N" (0 <= K < N), "auto" for a Slurm job array (K from
/// SLURM_ARRAY_TASK_ID, counted from SLURM_ARRAY_TASK_MIN in steps of
/// SLURM_ARRAY_TASK_STEP; N = SLURM_ARRAY_TASK_COUNT), or "auto/N" with K from
/// JOB_COMPLETION_INDEX (a Kubernetes indexed job) or SLURM_ARRAY_TASK_ID.
/// Throws UsageError naming the fix for bad text or missing variables.
render::FrameSegment parse_segment_option(const std::string& text, const EnvironmentLookup& environment);

}  // namespace vibra::cli
