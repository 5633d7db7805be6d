// The spelling rule of name_spelling.hpp: one comparison that every lookup of a name goes through.
#include "core/input/name_spelling.hpp"

#include <algorithm>

namespace vibra {

std::string name_key(std::string_view name) {
  std::string key(name);
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

bool same_name(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i] && !((a[i] == '-' || a[i] == '_') && (b[i] == '-' || b[i] == '_'))) return false;
  return true;
}

std::string listed_spelling(std::string_view name, const std::vector<std::string>& names) {
  for (const std::string& listed : names)
    if (same_name(name, listed)) return listed;
  return std::string(name);
}

}  // namespace vibra
