// The lecture page's decimated time series: a min/max envelope pyramid that
// keeps every extreme at every zoom level and stays within its byte budget.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/models/model.hpp"
#include "render/page/page_plots.hpp"
#include "scenes/panels/page_plot_collector.hpp"

using namespace vibra;
using render::ColumnEnvelope;
using render::PagePanel;
using render::PageSeriesData;

namespace {
std::vector<std::uint16_t> decode(const std::string& b64) {
  auto value = [](char c) -> unsigned {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    return c == '+' ? 62 : 63;
  };
  std::vector<std::uint8_t> bytes;
  for (size_t i = 0; i + 3 < b64.size(); i += 4) {
    const unsigned v = value(b64[i]) << 18 | value(b64[i + 1]) << 12 | (b64[i + 2] == '=' ? 0 : value(b64[i + 2]) << 6) |
                       (b64[i + 3] == '=' ? 0 : value(b64[i + 3]));
    bytes.push_back(v >> 16);
    if (b64[i + 2] != '=') bytes.push_back((v >> 8) & 255);
    if (b64[i + 3] != '=') bytes.push_back(v & 255);
  }
  std::vector<std::uint16_t> out;
  for (size_t i = 0; i + 1 < bytes.size(); i += 2) out.push_back(bytes[i] | bytes[i + 1] << 8);
  return out;
}

struct Level {
  long long cells;
  std::vector<std::uint16_t> values;
};

/// The levels of the JSON's series in order of appearance ("cells" then "data").
std::vector<Level> levels_of(const std::string& json) {
  std::vector<Level> out;
  for (size_t at = json.find("\"cells\":"); at != std::string::npos; at = json.find("\"cells\":", at + 1)) {
    const size_t data = json.find("\"data\":\"", at) + 8;
    out.push_back({std::stoll(json.substr(at + 8)), decode(json.substr(data, json.find('"', data) - data))});
  }
  return out;
}

std::string exact_data_of(const std::string& json) {
  const size_t exact = json.find("\"exact\":{");
  if (exact == std::string::npos) return "";
  const size_t data = json.find("\"data\":\"", exact) + 8;
  return json.substr(data, json.find('"', data) - data);
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("a column's extremes come in the order they happened, and survive coarsening", "[page]") {
  ColumnEnvelope e(8, 0, 8);
  for (double y : {0.0, 5.0, -3.0, 1.0}) e.add(0.5, y);  // max then min (samples at one x keep their order)
  for (double y : {0.0, -2.0, 4.0}) e.add(1.5, y);       // min then max
  e.add(2.5, 7.0);
  CHECK(*e.extremes_in_order(0) == std::pair(5.0, -3.0));
  CHECK(*e.extremes_in_order(1) == std::pair(-2.0, 4.0));
  CHECK(*e.extremes_in_order(2) == std::pair(7.0, 7.0));
  CHECK(!e.extremes_in_order(3));

  const ColumnEnvelope half = e.coarsened(2);
  REQUIRE(half.columns() == 4);
  CHECK(half.x1() == 8);
  CHECK(*half.extremes_in_order(0) == std::pair(5.0, -3.0));  // 5 at the start, -3 later, 4 < 5
  CHECK(*half.extremes_in_order(1) == std::pair(7.0, 7.0));
  const ColumnEnvelope all = e.coarsened(8);
  CHECK(*all.extremes_in_order(0) == std::pair(-3.0, 7.0));  // -3 before 7
}

TEST_CASE("1e7 samples: every zoom level keeps both spikes, the page's data stay in budget", "[page]") {
  const long long n = 10'000'000;
  const double dt = 1e-3;
  const long long peak = 6'543'210, dip = 1'234'567;
  PageSeriesData data(0, (n - 1) * dt, dt, n);
  for (long long i = 0; i < n; ++i) data.add(i == peak ? 3.0 : i == dip ? -2.0 : std::sin(0.0123 * i));
  CHECK(!data.has_exact());
  CHECK(data.lo() == -2.0);
  CHECK(data.hi() == 3.0);

  std::vector<PagePanel> panels(1);
  panels[0].label.assign(1, 'u');  // not = "u": GCC 12 warns falsely (-Wrestrict, bug 105651)
  panels[0].series.push_back({"u", "run", render::palette::blue, false, std::move(data)});
  const std::string json = render::page_plots_json(panels, render::kPagePlotBudgetBytes);
  CHECK(json.size() <= render::kPagePlotBudgetBytes);
  const std::vector<Level> levels = levels_of(json);
  REQUIRE(levels.size() >= 3);  // enough zoom: at least 2048, 8192 and 32768 cells
  CHECK(levels[0].cells == 2048);
  CHECK(exact_data_of(json).empty());
  for (const Level& level : levels) {
    INFO("level of " << level.cells << " cells");
    REQUIRE(level.values.size() == 2 * size_t(level.cells));
    const double width = (n - 1) * dt / level.cells;
    const long long peak_cell = std::llround(std::floor(peak * dt / width)), dip_cell = std::llround(std::floor(dip * dt / width));
    for (long long c = 0; c < level.cells; ++c) {
      const auto a = level.values[2 * c], b = level.values[2 * c + 1];
      CHECK((a == 65534 || b == 65534) == (c == peak_cell));  // the spike's cell alone reaches the top
      CHECK((a == 0 || b == 0) == (c == dip_cell));
      if (c != peak_cell && c != dip_cell && c % 97 == 0) {  // elsewhere sin's extremes, to 16 bits
        CHECK(std::max(a, b) <= std::lround(4.0 / 5 * 65534) + 1);
        CHECK(std::min(a, b) >= std::lround(1.0 / 5 * 65534) - 1);
      }
    }
  }
}

TEST_CASE("a short run is kept sample by sample, and many series share the budget", "[page]") {
  PageSeriesData data(0, 3, 0.1, 31);
  for (int i = 0; i <= 30; ++i) data.add(i * 0.1 * i * 0.1);
  std::vector<PagePanel> panels(1);
  panels[0].series.push_back({"u", "run", render::palette::blue, false, std::move(data)});
  const std::string json = render::page_plots_json(panels, render::kPagePlotBudgetBytes);
  CHECK(levels_of(json).empty());
  const std::vector<std::uint16_t> exact = decode(exact_data_of(json));
  REQUIRE(exact.size() == 31);
  for (int i = 0; i <= 30; ++i) CHECK(exact[i] * 9.0 / 65534 == Approx(i * 0.1 * i * 0.1).margin(9.0 / 65534));

  // 60 long series: coarser pyramids, never a failure, never over budget.
  std::vector<PagePanel> many(6);
  for (auto& panel : many)
    for (int k = 0; k < 10; ++k) {
      PageSeriesData d(0, 1, 1e-6, 1'000'001);
      for (int i = 0; i <= 1'000'000; i += 1) d.add(std::cos(1e-4 * i * (k + 1)));
      panel.series.push_back({"c", "run " + std::to_string(k), render::palette::green, false, std::move(d)});
    }
  const std::string big = render::page_plots_json(many, render::kPagePlotBudgetBytes);
  CHECK(big.size() <= render::kPagePlotBudgetBytes + 20'000);  // labels and numbers beside the data
  CHECK(count(big, "\"cells\":2048") == 60);
}

TEST_CASE("runs compared on one page: a curve per run in each panel, a legend key per run", "[page]") {
  std::vector<PagePanel> page;
  // dopri5's uneven steps reach the page on the same mesh as the others'.
  for (const char* scheme : {"rk4", "euler-cromer", "dopri5"}) {
    const ModelDefinition& model = find_model("pendulum");
    Parameters p = model_parameters(model);
    p.assign(std::string("scheme=") + scheme);
    p.assign("periods=2");
    p.assign("Theta=60");
    auto trajectory = model.build(p);
    scenes::PagePlotCollector collector(trajectory->info(), scenes::page_panel_names(trajectory->info()), scheme);
    std::vector<double> row(trajectory->width());
    do {
      trajectory->row(row);
      collector.observe(*trajectory, row);
    } while (trajectory->advance());
    scenes::merge_page_panels(page, collector.take_panels());
  }
  REQUIRE(page.size() == 3);
  CHECK(page[0].label == "θ (°)");
  for (const auto& panel : page) {
    REQUIRE(panel.series.size() == 3);
    CHECK(panel.series[0].key == "rk4");
    CHECK(panel.series[1].key == "euler-cromer");
    CHECK(panel.series[2].key == "dopri5");
    CHECK(panel.series[2].data.samples() == panel.series[0].data.samples());
  }
  // On the mesh, dopri5's theta (rtol 1e-6) is RK4's (dt = 2 pi/60) to well within a degree.
  const auto& rk4 = page[0].series[0].data.exact();
  const auto& dopri5 = page[0].series[2].data.exact();
  REQUIRE(rk4.size() == dopri5.size());
  double largest = 0;
  for (size_t i = 0; i < rk4.size(); ++i) largest = std::max(largest, double(std::abs(rk4[i] - dopri5[i])));
  CHECK(largest < 0.05);
  // theta is in degrees: Theta's default, 60 degrees, is the largest value.
  CHECK(page[0].series[0].data.hi() == Approx(60).epsilon(1e-12));
  const std::string json = render::page_plots_json(page, render::kPagePlotBudgetBytes);
  CHECK(count(json, "\"key\":\"rk4\"") == 3);
  CHECK(count(json, "\"key\":\"euler-cromer\"") == 3);
  CHECK(count(json, "\"key\":\"dopri5\"") == 3);
}

TEST_CASE("the page's time axis runs from the earliest start to the latest end of its series", "[page]") {
  // Two panels whose series cover different spans: the page's plots share
  // one time axis, from 0.5 (the second panel's start) to 5 (the first's end).
  std::vector<PagePanel> panels(2);
  PageSeriesData late(1, 5, 0.5, 9), early(0.5, 3, 0.25, 11);
  for (int i = 0; i < 9; ++i) late.add(i);
  for (int i = 0; i < 11; ++i) early.add(-i);
  panels[0].series.push_back({"u", "run", render::palette::blue, false, std::move(late)});
  panels[1].series.push_back({"v", "run", render::palette::blue, false, std::move(early)});
  const std::string json = render::page_plots_json(panels, render::kPagePlotBudgetBytes);
  CHECK(json.rfind("{\"t0\":0.5,\"t1\":5,", 0) == 0);
  // No series: the axis is [0, 1], not an empty or inverted one.
  CHECK(render::page_plots_json({}, render::kPagePlotBudgetBytes).rfind("{\"t0\":0,\"t1\":1,", 0) == 0);
}
