// RoadProfile (section 1.12.8): a road as heights every dx, with h(x) and h''(x).
#include "core/models/road_profile.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <random>
#include <sstream>

#include "core/error.hpp"
#include "core/input/input_files.hpp"

namespace vibra {

RoadProfile::RoadProfile(std::vector<double> heights, double dx) : h_(std::move(heights)), dx_(dx) {
  if (!(dx > 0) || std::isinf(dx)) throw UsageError("dx must be a positive length (the spacing of the road's heights)");
  if (h_.size() < 3) throw UsageError("a road needs at least 3 heights to have a curvature h''");
  const size_t n = h_.size();
  q_.resize(n);
  for (size_t i = 1; i + 1 < n; ++i) q_[i] = (h_[i + 1] - 2 * h_[i] + h_[i - 1]) / (dx * dx);
  q_[0] = q_[1];
  q_[n - 1] = q_[n - 2];
}

double RoadProfile::interpolate(const std::vector<double>& values, double x) const {
  const double position = std::clamp(x / dx_, 0.0, double(values.size() - 1));
  const size_t i = std::min(size_t(position), values.size() - 2);
  const double f = position - double(i);
  return (1 - f) * values[i] + f * values[i + 1];
}

double RoadProfile::height(double x) const { return interpolate(h_, x); }
double RoadProfile::curvature(double x) const { return interpolate(q_, x); }

namespace {
/// One height as the whole of [begin, end): a decimal number and nothing else.
bool read_height(const char* begin, const char* end, double& value) {
#if defined(__cpp_lib_to_chars)
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  return ec == std::errc() && ptr == end;
#else  // emscripten 3.1.6's libc++ (the browser build, web/) has no from_chars for double
  const std::string text(begin, end);
  if (text.empty() || text[0] == '+' || text.find_first_of("xX \t") != std::string::npos) return false;
  char* stop = nullptr;
  value = std::strtod(text.c_str(), &stop);
  return stop == text.c_str() + text.size();
#endif
}
}  // namespace

RoadProfile RoadProfile::from_file(const std::string& path, double dx) {
  std::istringstream in(read_input_file(path, "the road file", "the road profile (--set road)"));
  std::vector<double> heights;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const auto last = line.find_last_not_of(" \t\r");
    double value = 0;
    const char* begin = line.data() + first;
    const char* end = line.data() + last + 1;
    if (!read_height(begin, end, value) || !std::isfinite(value))
      throw UsageError(path + ":" + std::to_string(number) + ": '" + line.substr(first, last - first + 1) +
                       "' is not a height: the road file has one number per line");
    heights.push_back(value);
  }
  if (heights.empty()) throw UsageError("the road file '" + path + "' has no heights: one number per line");
  if (heights.size() < 3) throw UsageError("the road file '" + path + "' has fewer than 3 heights: a road needs at least 3");
  return RoadProfile(std::move(heights), dx);
}

RoadProfile RoadProfile::sine(double A, double wavelength, double length, double dx) {
  const size_t n = size_t(std::ceil(length / dx)) + 1;
  std::vector<double> h(std::max<size_t>(n, 3));
  for (size_t i = 0; i < h.size(); ++i) h[i] = A * std::sin(2 * M_PI * double(i) * dx / wavelength);
  return RoadProfile(std::move(h), dx);
}

RoadProfile RoadProfile::bumps(double A, double wavelength, double length, double dx, std::uint64_t seed) {
  const size_t n = std::max<size_t>(size_t(std::ceil(length / dx)) + 1, 3);
  std::vector<double> h(n, 0.0);
  // mt19937_64 is specified exactly by the standard; the uniform numbers are
  // made from its raw output so no library's distribution can change them.
  std::mt19937_64 random(seed);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * double(random() >> 11) * 0x1.0p-53; };
  for (double start = uniform(0.2, 1.0) * wavelength; start < double(n - 1) * dx; start += uniform(0.6, 1.4) * wavelength) {
    const double height = uniform(0.3, 1.0) * A, width = uniform(0.2, 0.5) * wavelength;
    const size_t i0 = size_t(std::ceil(start / dx)), i1 = std::min(n - 1, size_t((start + width) / dx));
    for (size_t i = i0; i <= i1; ++i)
      h[i] += 0.5 * height * (1 - std::cos(2 * M_PI * (double(i) * dx - start) / width));
  }
  return RoadProfile(std::move(h), dx);
}

}  // namespace vibra
