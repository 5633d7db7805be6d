// How many notes one frame has room for, and the refusal of more shown at once.
#include "scenes/overlays/note_room.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/input/quoted_value.hpp"
#include "core/stop_flag.hpp"
#include "render/draw/canvas.hpp"

namespace vibra::scenes {

namespace {
/// How many cards of `size` pixels fit in `room` pixels, at least one.
long long fitting(double room, double size) { return std::max(1LL, static_cast<long long>(std::floor(room / size))); }
}  // namespace

long long most_notes_at_once(int width, int height) {
  const double scale = render::scale_for_height(height);
  const double card_height = (kNoteCard.text + 2 * kNoteCard.padding) * scale;
  return fitting(height, card_height) * fitting(width, kNoteCard.least_room * scale);
}

void refuse_crowded_notes(const std::vector<Note>& notes, int width, int height) {
  const long long limit = most_notes_at_once(width, height);
  if (static_cast<long long>(notes.size()) <= limit) return;
  // A note is shown from its first time to its last, both included: starts before ends at one time.
  std::vector<std::pair<double, int>> changes;
  changes.reserve(2 * notes.size());
  for (const Note& note : notes) changes.push_back({note.from, -1}), changes.push_back({note.to, +1});
  std::sort(changes.begin(), changes.end());
  long long shown = 0;
  for (std::size_t i = 0; i < changes.size(); ++i) {
    if ((i & 0xffff) == 0xffff) throw_if_stop_requested();
    const auto [t, change] = changes[i];
    shown -= change;
    const bool more_start_now = i + 1 < changes.size() && changes[i + 1] == std::pair{t, -1};
    if (shown > limit && !more_start_now)  // all that start at t counted: the most shown then
      throw UsageError(std::to_string(shown) + " notes are shown at t = " + short_number(t) + ": a " +
                       std::to_string(width) + "x" + std::to_string(height) + " frame shows at most " +
                       std::to_string(limit) + " at once: give them shorter or later times, or fewer notes");
  }
}

}  // namespace vibra::scenes
