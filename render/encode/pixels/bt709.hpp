// BT.709's luma weights, shared by the 8-bit YUV and the YUVA converters.
#pragma once

namespace vibra::render::bt709 {

/// Y = Kr R + Kg G + Kb B (ITU-R BT.709), on colour in 0..1.
constexpr double kKr = 0.2126, kKb = 0.0722, kKg = 1 - kKr - kKb;

}  // namespace vibra::render::bt709
