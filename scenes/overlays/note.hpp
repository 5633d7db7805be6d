// Notes (--note "T0-T1: TEXT", scene key notes): text shown over a time window of a render.
#pragma once
#include <string>

namespace vibra::scenes {

/// A callout on a render (`--note "T0-T1: TEXT"`, scene key `notes`): TEXT,
/// which may hold $math$ in the typesetter's subset, is shown for frames
/// with T0 <= t <= T1; with "@PANEL" at its end it points at that panel's
/// curve at T0.
struct Note {
  double from = 0, to = 0;
  std::string text;   ///< rich text: plain words and $math$
  std::string panel;  ///< "" = placed near the diagram's body
  bool shown_at(double t) const { return t >= from && t <= to; }
};

/// Reads "T0-T1: TEXT" or "T0-T1: TEXT @PANEL" (T0 <= T1, numbers such as
/// 2, 2.5 or 1e1). Throws UsageError, one line naming the problem and the
/// fix, for bad syntax or bad math in TEXT.
Note parse_note(const std::string& spec);

}  // namespace vibra::scenes
