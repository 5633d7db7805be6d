// A lecture's shot rendered into a video of its own, with its first frame: what slides and a folder of shots are made of.
#include "scenes/lecture/presented_shot.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace vibra::scenes {

std::string shot_file_stem(const PresentedShot& shot, std::size_t shots) {
  constexpr std::size_t kLongestTitle = 40;  // characters of the title kept in a name
  const int width = std::max(2, int(std::to_string(shots).size()));
  char number[16];
  std::snprintf(number, sizeof number, "%0*d", width, shot.number);
  std::string name = number;
  bool gap = true;  // one '-' between words, none doubled
  for (unsigned char c : shot.title) {
    if (name.size() >= width + 1 + kLongestTitle) break;
    if (std::isalnum(c) && c < 128) {
      if (gap) name += '-';
      name += char(std::tolower(c));
      gap = false;
    } else {
      gap = true;
    }
  }
  return name;
}

}  // namespace vibra::scenes
