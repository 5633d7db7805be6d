// How many notes one frame has room for, and the refusal of more shown at once.
#pragma once
#include <vector>

#include "scenes/overlays/note.hpp"

namespace vibra::scenes {

/// A note's card, in 720p pixels (scaled with the frame's height as every
/// drawing is): its text size, and the least room it is given across.
struct NoteCardSize {
  double text = 17;        ///< the note's text
  double padding = 5;      ///< around the text on its card (the label placer's card_padding)
  double least_room = 120; ///< across, at least (note_callouts.cpp breaks longer notes into lines)
};
inline constexpr NoteCardSize kNoteCard{};

/// The most notes a width x height frame shows at once: rows of cards one
/// line tall down its height, times cards of the least room across its width
/// (260 at 1280x720). More could not be placed apart, and placing each costs
/// a look at every one placed before it.
long long most_notes_at_once(int width, int height);

/// Throws UsageError when more notes than that are shown at one time,
/// naming the time, the count and the limit. Polls the stop flag.
void refuse_crowded_notes(const std::vector<Note>&, int width, int height);

}  // namespace vibra::scenes
