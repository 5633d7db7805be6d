// The page's controls from the CLI's own tables: a model's keys (meaning, unit, default, choices) with their ranges, as JSON.
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/models/model.hpp"
#include "core/input/value_ranges.hpp"

namespace {

/// What kind of control a key gets, by its ValueKind.
constexpr const char* kControlOf[] = {"number", "angle", "formula", "choice", "text"};

std::string json_text(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) out += ' ';  // no control characters in one line of help
    else out += c;
  }
  return out + "\"";
}

std::string json_list(const std::vector<std::string>& items) {
  std::string out = "[";
  for (const auto& item : items) out += (out.size() > 1 ? "," : "") + json_text(item);
  return out + "]";
}

/// A bound as JSON: 1e+15 as 1e15, every double exactly (17 digits).
std::string json_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// The row of the range table that checks a key: its own, "angle" for an angle key, else "model number".
const vibra::ValueRange& range_of(const vibra::KeySpec& key) {
  return key.kind == vibra::ValueKind::angle ? vibra::value_range("angle") : vibra::value_range(key.name);
}

std::string json_key(const vibra::KeySpec& key) {
  std::string out = "{\"name\":" + json_text(key.name) + ",\"control\":\"" + kControlOf[int(key.kind)] + "\"" +
                    ",\"default\":" + json_text(key.default_value) + ",\"unit\":" + json_text(key.unit) +
                    ",\"meaning\":" + json_text(key.meaning) + ",\"choices\":" + json_list(key.choices) +
                    ",\"variables\":" + json_list(key.variables);
  if (key.kind == vibra::ValueKind::number || key.kind == vibra::ValueKind::angle) {
    const vibra::ValueRange& r = range_of(key);
    out += ",\"range\":{\"lo\":" + json_number(r.lo) + ",\"hi\":" + json_number(r.hi) +
           ",\"lo_excluded\":" + (r.lo_excluded ? "true" : "false") + ",\"whole\":" + (r.whole ? "true" : "false") +
           ",\"inf_allowed\":" + (r.inf_allowed ? "true" : "false") + "}";
  }
  return out + "}";
}

std::string last_table;

}  // namespace

extern "C" {

/// The keys of MODEL, as `vibra solve MODEL --help` lists them, in a JSON
/// array; "" for an unknown model (vibra_solve names the problem).
const char* vibra_model_keys(const char* model) {
  last_table.clear();
  try {
    const vibra::Parameters p = vibra::model_parameters(vibra::find_model(model ? model : ""));
    for (const auto& key : p.specs()) last_table += (last_table.empty() ? "[" : ",") + json_key(key);
    last_table += last_table.empty() ? "[]" : "]";
  } catch (const vibra::UsageError&) {
    last_table.clear();
  }
  return last_table.c_str();
}

}  // extern "C"
