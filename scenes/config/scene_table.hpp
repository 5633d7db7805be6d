// A TOML table of scene keys read as settings: what scene files hold, and what a storyboard's shots hold beside their own keys.
#pragma once
#include <toml++/toml.h>

#include <string>
#include <vector>

#include "scenes/config/scene_config.hpp"

namespace vibra::scenes {

/// The table's keys as settings, one per key (one per item of a slow or
/// pause list; [colors] as colors.bob ...). Each setting's origin is
/// "FILE:LINE", followed by ": WHERE, KEY" when `where` is given (a
/// storyboard's "shot 2"). Top-level keys in `skip` are left out (a shot's
/// own keys). Throws UsageError for a value that is not a number, string or
/// boolean, or a table nested too deeply.
/// The longest key a scene file or storyboard may hold: longer is no key of vibra's.
inline constexpr std::size_t kLongestKey = 64;

/// Throws UsageError, one line naming the line and the limit (and not the
/// key), for a key longer than kLongestKey anywhere in `table` (its tables
/// and arrays of tables, 8 levels deep), before any key is looked up.
void refuse_long_keys(const toml::table&, const std::string& file);

std::vector<Setting> table_settings(const toml::table&, const std::string& file, const std::string& where = "",
                                    const std::vector<std::string>& skip = {});

}  // namespace vibra::scenes
