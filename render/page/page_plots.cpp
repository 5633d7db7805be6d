// A lecture page's plots: curves decimated to min/max envelopes and packed into the page.
#include "render/page/page_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>

#include "render/page/web_text.hpp"

namespace vibra::render {

namespace {
constexpr int kBaseColumns = 2048;  ///< a level with a cell per pixel of a wide plot
constexpr int kLevelFactor = 4;
constexpr std::uint16_t kEmpty = 65535;

int finest_columns(long long samples) {
  long long columns = kBaseColumns;
  while (2 * columns < samples && columns < PageSeriesData::kMaxColumns) columns *= kLevelFactor;
  return static_cast<int>(columns);
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

std::string hex_color(const Color& c) {
  char text[8];
  auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return text;
}

/// 16-bit steps of [lo, hi], little-endian, with kEmpty for a missing value.
class Quantizer {
 public:
  Quantizer(double lo, double hi) : lo_(lo), scale_(hi > lo ? 65534 / (hi - lo) : 0) {}
  void add(std::optional<double> y) {
    const std::uint16_t q = y && std::isfinite(*y) ? static_cast<std::uint16_t>(std::lround(
                                                         std::clamp((*y - lo_) * scale_, 0.0, 65534.0)))
                                                   : kEmpty;
    bytes_.push_back(q & 0xff);
    bytes_.push_back(q >> 8);
  }
  std::string base64_text() const { return base64(bytes_); }

 private:
  double lo_, scale_;
  std::vector<std::uint8_t> bytes_;
};

std::string series_json(const PageSeries& s, long long budget_values) {
  const PageSeriesData& d = s.data;
  const double lo = d.lo() <= d.hi() ? d.lo() : 0, hi = d.lo() <= d.hi() ? d.hi() : 0;
  const long long n = d.samples();
  const ColumnEnvelope& finest = d.envelope();

  // Coarse to fine, 4x a level, while the budget lasts and a level still
  // decimates; then every sample, if kept and affordable.
  std::vector<int> levels;
  long long used = 0;
  const bool exact_only = d.has_exact() && n <= budget_values && n <= 2 * kBaseColumns;
  if (!exact_only) {
    int base = kBaseColumns;
    while (base > 16 && 2LL * base > budget_values) base /= 2;
    for (long long c = base; c <= finest.columns(); c *= kLevelFactor) {
      if (!levels.empty() && (2 * c >= n || used + 2 * c > budget_values)) break;
      levels.push_back(static_cast<int>(c));
      used += 2 * c;
    }
  }
  const bool with_exact = d.has_exact() && used + n <= budget_values;

  std::string out = "{\"label\":" + json_string(s.label) + ",\"key\":" + json_string(s.key) +
                    ",\"color\":\"" + hex_color(s.color) + "\",\"dash\":" + (s.dashed ? "true" : "false") +
                    ",\"lo\":" + number(lo) + ",\"hi\":" + number(hi) + ",\"t0\":" + number(finest.x0()) +
                    ",\"t1\":" + number(finest.x1()) + ",\"levels\":[";
  for (size_t i = 0; i < levels.size(); ++i) {
    const ColumnEnvelope level = finest.coarsened(finest.columns() / levels[i]);
    Quantizer q(lo, hi);
    for (int c = 0; c < level.columns(); ++c) {
      const auto pair = level.extremes_in_order(c);
      q.add(pair ? std::optional(pair->first) : std::nullopt);
      q.add(pair ? std::optional(pair->second) : std::nullopt);
    }
    if (i) out += ',';
    out += "{\"cells\":" + std::to_string(level.columns()) + ",\"data\":\"" + q.base64_text() + "\"}";
  }
  out += "],\"exact\":";
  if (with_exact) {
    Quantizer q(lo, hi);
    for (float y : d.exact()) q.add(y);
    out += "{\"t0\":" + number(d.t0()) + ",\"dt\":" + number(d.dt()) + ",\"count\":" + std::to_string(n) +
           ",\"data\":\"" + q.base64_text() + "\"}";
  } else {
    out += "null";
  }
  return out + "}";
}
}  // namespace

PageSeriesData::PageSeriesData(double t0, double t_end, double dt, long long samples)
    : t0_(t0), dt_(dt), envelope_(finest_columns(samples), t0, t_end) {
  if (samples <= kMaxExactSamples) exact_.reserve(static_cast<size_t>(std::max(0LL, samples)));
}

void PageSeriesData::add(double y) {
  envelope_.add(t0_ + count_ * dt_, y);
  if (count_ < kMaxExactSamples) {
    exact_.push_back(static_cast<float>(y));
  } else if (count_ == kMaxExactSamples) {
    exact_.clear();
    exact_.shrink_to_fit();
  }
  ++count_;
  if (std::isfinite(y)) lo_ = std::min(lo_, y), hi_ = std::max(hi_, y);
}

std::string page_plots_json(const std::vector<PagePanel>& panels, size_t budget_bytes) {
  size_t series = 0;
  double t0 = 1e300, t1 = -1e300;
  for (const auto& panel : panels)
    for (const auto& s : panel.series) {
      ++series;
      t0 = std::min(t0, s.data.t0());
      t1 = std::max(t1, s.data.t_end());
    }
  if (!series) t0 = 0, t1 = 1;
  // base64 carries 3 bytes in 4 characters; a value is 2 bytes.
  const long long budget_values = static_cast<long long>(budget_bytes / 4 * 3 / 2 / std::max<size_t>(1, series));
  std::string out = "{\"t0\":" + number(t0) + ",\"t1\":" + number(t1) + ",\"panels\":[";
  for (size_t p = 0; p < panels.size(); ++p) {
    if (p) out += ',';
    out += "{\"label\":" + json_string(panels[p].label) + ",\"series\":[";
    for (size_t i = 0; i < panels[p].series.size(); ++i) {
      if (i) out += ',';
      out += series_json(panels[p].series[i], budget_values);
    }
    out += "]}";
  }
  return out + "]}";
}

}  // namespace vibra::render
