// A software stroke for plain strokes on image surfaces, pixel-equal to Cairo's own but faster.
#include "render/draw/stroke_raster.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>
#if defined(__x86_64__)
#include <immintrin.h>
#define AVX2_OR_NULL(loop) loop
#else
#define AVX2_OR_NULL(loop) nullptr  // no such loop off x86-64
#endif

namespace vibra::render {

namespace {
/// A join that turns by less than this looks the same round, mitred or
/// bevelled: at 25 degrees a mitre reaches 0.03 px beyond a round join on a
/// 2.4 px line.
const double kInvisibleJoinCos = std::cos(25 * M_PI / 180);

/// More dashes than this in one subpath are left to Cairo.
constexpr double kMostDashes = 100000;

struct XY {
  double x, y;
  bool operator==(const XY&) const = default;
};

/// A straight edge a stroke ends at: pixels behind it, against `dir`, are
/// not covered (ramped over a pixel, as a cut end is).
struct Fence {
  XY at{0, 0}, dir{0, 0};
  bool up = false;
};

/// One piece of a stroke in target pixels: a straight segment whose ends
/// are round (a join or a round cap) or cut square across at the end point;
/// fences keep the round ends (joins) of a piece near a cut end from
/// bulging out past the cut, as Cairo's join (a wedge, not a disc) does not.
struct Piece {
  Piece(const XY& from, const XY& to, bool cut_from = false, bool cut_to = false)
      : a(from), b(to), cut_a(cut_from), cut_b(cut_to) {}
  XY a, b;
  bool cut_a, cut_b;
  Fence start, end;
};

/// How the stroke looks, as the context says.
struct Style {
  double half_width = 0;
  cairo_line_cap_t cap = CAIRO_LINE_CAP_ROUND;
  cairo_line_join_t join = CAIRO_LINE_JOIN_ROUND;
  std::vector<double> dashes;  ///< on, off, on, ... lengths; empty: solid
  double dash_offset = 0;      ///< into the pattern, in [0, its length)
};

/// Everything a software stroke needs from the context.
struct Plan {
  std::vector<Piece> pieces;
  double half_width = 0;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< the clip in target pixels, [x0, x1) x [y0, y1)
  std::uint32_t source = 0;  ///< the colour as an ARGB32 pixel, premultiplied
  bool scalar = false;       ///< one pixel at a time (the check of the vector loops)
};

struct PathDeleter {
  void operator()(cairo_path_t* p) const { cairo_path_destroy(p); }
};
struct RectanglesDeleter {
  void operator()(cairo_rectangle_list_t* l) const { cairo_rectangle_list_destroy(l); }
};

XY unit(const XY& from, const XY& to) {
  const double dx = to.x - from.x, dy = to.y - from.y, length = std::sqrt(dx * dx + dy * dy);
  return {dx / length, dy / length};
}

/// Adds the pieces of one drawn run of points (distinct neighbours): a whole
/// subpath, or a dash. `along` is the direction a one-point run (a dash of no
/// length) lies in. False when Cairo must draw it: a join that turns enough
/// for a non-round style to show, or a square dot.
bool add_run(std::vector<Piece>& pieces, const std::vector<XY>& run, bool closed, const XY& along, const Style& style) {
  const std::size_t n = run.size();
  if (n == 0) return true;
  const double h = style.half_width;
  if (n == 1) {  // a dot: round caps draw a disc, butt caps nothing, square caps a square across `along`
    if (closed || style.cap == CAIRO_LINE_CAP_BUTT) return !closed;
    if (style.cap == CAIRO_LINE_CAP_ROUND) {
      pieces.push_back({run[0], run[0]});
      return true;
    }
    if (!std::isfinite(along.x)) return false;
    pieces.push_back({{run[0].x - h * along.x, run[0].y - h * along.y},
                      {run[0].x + h * along.x, run[0].y + h * along.y}, true, true});
    return true;
  }
  const std::size_t segments = closed ? n : n - 1;
  if (style.join != CAIRO_LINE_JOIN_ROUND)
    for (std::size_t s = closed ? 0 : 1; s < segments; ++s) {
      const std::size_t before = (s + segments - 1) % segments;
      const XY u = unit(run[before], run[(before + 1) % n]), v = unit(run[s], run[(s + 1) % n]);
      if (u.x * v.x + u.y * v.y < kInvisibleJoinCos) return false;
    }
  const bool cut = !closed && style.cap != CAIRO_LINE_CAP_ROUND;
  Fence start, end;
  std::vector<double> from_start;  // with a cut end: path length to each point
  if (cut) {
    from_start.assign(n, 0.0);
    // A square cap is a butt cap half a width further out.
    const double extend = style.cap == CAIRO_LINE_CAP_SQUARE ? h : 0;
    const XY u = unit(run[0], run[1]), v = unit(run[n - 2], run[n - 1]);
    start = {{run[0].x - extend * u.x, run[0].y - extend * u.y}, u, true};
    end = {{run[n - 1].x + extend * v.x, run[n - 1].y + extend * v.y}, {-v.x, -v.y}, true};
    for (std::size_t i = 1; i < n; ++i) from_start[i] = from_start[i - 1] + std::hypot(run[i].x - run[i - 1].x, run[i].y - run[i - 1].y);
  }
  for (std::size_t s = 0; s < segments; ++s) {
    Piece p{run[s], run[(s + 1) % n]};
    if (cut) {
      if (s == 0) p.cut_a = true, p.a = start.at;
      if (s + 1 == segments) p.cut_b = true, p.b = end.at;
      // A join disc within reach of a cut end stops at it.
      if (s > 0 && from_start[s] < h + 1) p.start = start;
      if (s + 1 < segments && from_start[n - 1] - from_start[s + 1] < h + 1) p.end = end;
    }
    pieces.push_back(p);
  }
  return true;
}

/// Whether dashing the subpath would make more pieces than kMostDashes
/// (dashes far finer than a pixel would be millions): Cairo's, then.
bool too_many_dashes(const std::vector<XY>& points, bool closed, const Style& style) {
  double length = 0, period = 0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) length += std::hypot(points[i + 1].x - points[i].x, points[i + 1].y - points[i].y);
  if (closed) length += std::hypot(points[0].x - points.back().x, points[0].y - points.back().y);
  for (double d : style.dashes) period += d;
  return length / period * double(style.dashes.size()) > kMostDashes;
}

/// Where a subpath is in the dash pattern, as Cairo steps through it: a dash
/// ends where less than its fixed point's resolution of it remains, so a
/// pattern that ends exactly at the path's end starts its next dash there (a
/// dot, with round caps). Unlike Cairo, the remainder is carried to the next
/// dash, so that the dashes stay where the path's length puts them.
struct DashPhase {
  static constexpr double kResolution = 1.0 / 256;
  const std::vector<double>& dashes;
  std::size_t index = 0;
  bool on = true;
  double remain = 0;  ///< of the current dash (or gap)

  /// At the subpath's start, where the dash offset puts it.
  explicit DashPhase(const Style& style) : dashes(style.dashes) {
    double offset = style.dash_offset;
    while (offset > 0 && offset >= dashes[index]) {
      offset -= dashes[index];
      next();
    }
    // A dash of no length here is still a dash: add_subpath ends it at the
    // start, a dot with round caps, as Cairo draws it (it stops skipping
    // dashes when the offset reaches 0 for that reason).
    remain = dashes[index] - offset;
  }
  void next() {
    on = !on;
    index = (index + 1) % dashes.size();
  }
  /// On to the next dash (or gap), what was left of this one carried over.
  void next_dash() {
    next();
    remain += dashes[index];
  }
  bool ended() const { return remain < kResolution; }
};

void drop_repeats(std::vector<XY>& run) { run.erase(std::unique(run.begin(), run.end()), run.end()); }

/// Adds one subpath's pieces, dashed as Cairo dashes: the pattern starts
/// afresh at each subpath, and on a closed one a dash running through the
/// start joins the dash it started with.
bool add_subpath(std::vector<Piece>& pieces, std::vector<XY>& points, bool closed, bool has_line, const Style& style) {
  drop_repeats(points);  // repeated points have no direction
  if (closed && points.size() > 1 && points.front() == points.back()) points.pop_back();
  if (points.empty() || !has_line) return true;  // a lone move draws nothing
  const XY none{NAN, NAN};
  if (style.dashes.empty() || points.size() == 1) return add_run(pieces, points, closed, none, style);
  if (too_many_dashes(points, closed, style)) return false;

  DashPhase dash(style);
  // On a closed subpath the dash running through the start is held back:
  // the last dash, if it runs to the start, goes on into it.
  const bool hold_first = closed && dash.on;
  std::vector<XY> first_run, run;
  bool first_ended = false;
  auto end_run = [&](const XY& along) {
    drop_repeats(run);
    const bool ok = hold_first && !first_ended ? (first_run = run, true) : add_run(pieces, run, false, along, style);
    first_ended = true;
    run.clear();
    return ok;
  };
  if (dash.on) run.push_back(points[0]);
  const std::size_t n = points.size(), segments = closed ? n : n - 1;
  for (std::size_t s = 0; s < segments; ++s) {
    const XY& a = points[s];
    const XY& b = points[(s + 1) % n];
    const XY u = unit(a, b);
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    for (double at = 0; at < length;) {
      const double step = std::min(dash.remain, length - at);
      at += step;
      dash.remain -= step;
      const XY q = at >= length ? b : XY{a.x + at * u.x, a.y + at * u.y};
      if (dash.on) run.push_back(q);
      if (!dash.ended()) continue;
      if (dash.on && !end_run(u)) return false;  // a dash ends at q
      if (!dash.on) run.push_back(q);             // a dash starts at q
      dash.next_dash();
    }
  }
  const XY last_along = closed ? unit(points[n - 1], points[0]) : unit(points[n - 2], points[n - 1]);
  if (!hold_first) return !dash.on || end_run(last_along);
  if (!first_ended) {  // on all the way round: no dash ever ended
    run.pop_back();     // the start again
    drop_repeats(run);
    return add_run(pieces, run, true, last_along, style);
  }
  if (dash.on) run.insert(run.end(), first_run.begin(), first_run.end());  // the last dash runs on into the first
  else run = std::move(first_run);
  drop_repeats(run);
  return add_run(pieces, run, false, unit(points[0], points[1]), style);
}

/// The stroke's look, or false when it is not one this file draws.
bool read_style(cairo_t* cr, Style& style) {
  const double width = cairo_get_line_width(cr);
  if (!(width > 0) || !std::isfinite(width)) return false;
  style.half_width = width / 2;
  style.cap = cairo_get_line_cap(cr);
  style.join = cairo_get_line_join(cr);
  const int count = cairo_get_dash_count(cr);
  if (count == 0) return true;
  style.dashes.resize(count);
  cairo_get_dash(cr, style.dashes.data(), &style.dash_offset);
  double total = 0;
  for (double d : style.dashes) {
    if (!(d >= 0) || !std::isfinite(d)) return false;
    total += d;
  }
  if (count % 2 == 1) total *= 2;  // an odd pattern repeats with on and off swapped
  if (!(total > 0)) return false;
  style.dash_offset = std::fmod(style.dash_offset, total);
  if (style.dash_offset < 0) style.dash_offset += total;
  return std::isfinite(style.dash_offset);
}

/// The plan for stroking `cr`'s path in software, or false when Cairo must.
bool plan_stroke(cairo_t* cr, cairo_surface_t* target, Plan& plan) {
  if (cairo_surface_get_type(target) != CAIRO_SURFACE_TYPE_IMAGE ||
      cairo_image_surface_get_format(target) != CAIRO_FORMAT_ARGB32 || cairo_get_operator(cr) != CAIRO_OPERATOR_OVER ||
      cairo_get_antialias(cr) == CAIRO_ANTIALIAS_NONE)
    return false;
  double red, green, blue, alpha;
  cairo_pattern_t* source = cairo_get_source(cr);
  if (cairo_pattern_get_type(source) != CAIRO_PATTERN_TYPE_SOLID ||
      cairo_pattern_get_rgba(source, &red, &green, &blue, &alpha) != CAIRO_STATUS_SUCCESS)
    return false;
  cairo_matrix_t m;
  cairo_get_matrix(cr, &m);
  if (m.xx != 1 || m.yy != 1 || m.xy != 0 || m.yx != 0) return false;
  double scale_x, scale_y, offset_x, offset_y;
  cairo_surface_get_device_scale(target, &scale_x, &scale_y);
  if (scale_x != 1 || scale_y != 1) return false;
  cairo_surface_get_device_offset(target, &offset_x, &offset_y);
  const double shift_x = m.x0 + offset_x, shift_y = m.y0 + offset_y;  // user space to target pixels
  Style style;
  if (!read_style(cr, style)) return false;
  plan.half_width = style.half_width;

  const std::unique_ptr<cairo_rectangle_list_t, RectanglesDeleter> clip(cairo_copy_clip_rectangle_list(cr));
  if (clip->status != CAIRO_STATUS_SUCCESS || clip->num_rectangles > 1) return false;  // not whole-pixel rectangles
  if (clip->num_rectangles == 1) {
    const cairo_rectangle_t& r = clip->rectangles[0];
    const double x0 = std::max(0.0, r.x + shift_x), y0 = std::max(0.0, r.y + shift_y);
    const double x1 = std::min<double>(cairo_image_surface_get_width(target), r.x + r.width + shift_x);
    const double y1 = std::min<double>(cairo_image_surface_get_height(target), r.y + r.height + shift_y);
    if (x0 != std::floor(x0) || y0 != std::floor(y0) || x1 != std::floor(x1) || y1 != std::floor(y1)) return false;
    if (x1 > x0 && y1 > y0) plan.x0 = int(x0), plan.y0 = int(y0), plan.x1 = int(x1), plan.y1 = int(y1);
  }

  const std::unique_ptr<cairo_path_t, PathDeleter> path(cairo_copy_path_flat(cr));
  if (path->status != CAIRO_STATUS_SUCCESS) return false;
  std::vector<XY> points;  // the current subpath's
  bool has_line = false;
  for (int i = 0; i < path->num_data; i += path->data[i].header.length) {
    const cairo_path_data_t& d = path->data[i];
    if (d.header.type == CAIRO_PATH_MOVE_TO || d.header.type == CAIRO_PATH_CLOSE_PATH) {
      const bool closed = d.header.type == CAIRO_PATH_CLOSE_PATH;
      const XY start = points.empty() ? XY{0, 0} : points.front();
      if (!add_subpath(plan.pieces, points, closed, has_line, style)) return false;
      points.clear();
      if (closed && has_line) points.push_back(start);  // the next subpath starts where this one did
      has_line = false;
    }
    if (d.header.type == CAIRO_PATH_MOVE_TO || d.header.type == CAIRO_PATH_LINE_TO) {
      const XY p{path->data[i + 1].point.x + shift_x, path->data[i + 1].point.y + shift_y};
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
      if (d.header.type == CAIRO_PATH_MOVE_TO) points.clear();
      else has_line = true;
      points.push_back(p);
    }
  }
  if (!add_subpath(plan.pieces, points, false, has_line, style)) return false;

  const double a = std::clamp(alpha, 0.0, 1.0);
  const double channels[4] = {blue, green, red, 1.0};
  for (int c = 0; c < 4; ++c)
    plan.source |= std::uint32_t(std::lround(std::clamp(channels[c], 0.0, 1.0) * a * 255)) << (8 * c);
  return true;
}

/// Coverage in [0, 1] as an 8-bit mask. Rounding keeps order, so the mask of
/// the largest coverage is the largest mask: pieces join by taking the
/// larger mask, in a quarter of the memory floats would take.
inline std::uint8_t mask_of(double coverage) { return static_cast<std::uint8_t>(float(coverage) * 255 + 0.5f); }

/// `value` rounded down (up) to an int within [lo, hi]: far-off points stay in range.
int floor_within(double value, int lo, int hi) { return int(std::clamp(std::floor(value), double(lo), double(hi))); }
int ceil_within(double value, int lo, int hi) { return int(std::clamp(std::ceil(value), double(lo), double(hi))); }

/// Each of the four 8-bit channels of `x` times a / 255, rounded as pixman
/// rounds (two channels at a time, in the halves of a word).
inline std::uint32_t times_alpha(std::uint32_t x, std::uint32_t a) {
  std::uint32_t rb = (x & 0xff00ff) * a + 0x800080;
  rb = ((rb + ((rb >> 8) & 0xff00ff)) >> 8) & 0xff00ff;
  std::uint32_t ag = ((x >> 8) & 0xff00ff) * a + 0x800080;
  ag = (ag + ((ag >> 8) & 0xff00ff)) & 0xff00ff00;
  return rb | ag;
}

/// Coverage of the clip's pixels, kept zero between strokes: each stroke
/// clears what it touched.
struct Coverage {
  std::vector<std::uint8_t> cells;  ///< coverage as the 8-bit mask it is blended with
  std::vector<int> lo, hi;  ///< per row of the clip, the columns touched ([lo, hi], empty when lo > hi)
  int first_row = INT_MAX, last_row = INT_MIN;  ///< the rows touched
  /// Ready for a stroke in a clip of `width` x `height` (all untouched: the
  /// last stroke put back what it touched, so a stroke costs what it covers).
  void prepare(int width, int height) {
    // 7 cells of room past the last: the vector loops read and rewrite them unchanged.
    if (cells.size() < std::size_t(width) * height + 7) cells.assign(std::size_t(width) * height + 7, 0);
    if (lo.size() < std::size_t(height)) lo.assign(height, INT_MAX), hi.assign(height, INT_MIN);
  }
  void touch(int r, int first, int last) {
    lo[r] = std::min(lo[r], first), hi[r] = std::max(hi[r], last);
    first_row = std::min(first_row, r), last_row = std::max(last_row, r);
  }
};

/// A piece measured for covering: its half width, reach, direction and length.
struct PieceGeometry {
  double h, reach;  ///< half the line width; coverage falls to 0 half a pixel outside the line
  /// A disc's coverage ramped over a pixel of distance holds pi (h^2 + 1/12)
  /// of ink, not pi h^2: a round end drawn this much smaller holds the right
  /// amount (a thin line's dashes were 3% too dark).
  double round_end;
  double dx, dy, length, ux, uy;
  PieceGeometry(const Piece& p, double half_width)
      : h(half_width), reach(half_width + 0.5), round_end(1 / (24 * half_width)), dx(p.b.x - p.a.x),
        dy(p.b.y - p.a.y), length(std::sqrt(dx * dx + dy * dy)), ux(length > 0 ? dx / length : 1),
        uy(length > 0 ? dy / length : 0) {}
};

/// The columns [first, last] of row `row` within reach of a long piece: its
/// stretch within `reach` of the row's centre line, widened by `reach`.
/// False when the row is beyond the piece.
bool long_piece_columns(const Piece& p, const PieceGeometry& g, const Plan& plan, int row, int& first, int& last) {
  const double cy = row + 0.5;
  double t0 = 0, t1 = 1;
  if (g.dy != 0) {
    t0 = (cy - g.reach - p.a.y) / g.dy, t1 = (cy + g.reach - p.a.y) / g.dy;
    if (t0 > t1) std::swap(t0, t1);
    t0 = std::max(t0, 0.0), t1 = std::min(t1, 1.0);
    if (t0 > t1) return false;
  } else if (std::abs(cy - p.a.y) > g.reach) {
    return false;
  }
  const double xa = p.a.x + t0 * g.dx, xb = p.a.x + t1 * g.dx;
  first = ceil_within(std::min(xa, xb) - g.reach - 0.5, plan.x0, plan.x1);
  last = floor_within(std::max(xa, xb) + g.reach - 0.5, plan.x0 - 1, plan.x1 - 1);
  return true;
}

/// One row's pixels of a piece round at both ends with nothing to cut: the
/// common piece, without branches. Each pixel's own distance along and
/// across the segment from its start, not stepped column by column, so that
/// a pixel's coverage is the same whatever part of the row a clip lets the
/// stroke touch.
void cover_plain_row_scalar(const Piece& p, const PieceGeometry& g, int row, int first, int last, std::uint8_t* cells) {
  const double py = row + 0.5 - p.a.y;
  for (int column = first; column <= last; ++column) {
    const double px = column + 0.5 - p.a.x;
    const double along = px * g.ux + py * g.uy, across = px * g.uy - py * g.ux;
    const double beyond = std::max({0.0, -along, along - g.length});
    const double distance = beyond > 0 ? std::sqrt(beyond * beyond + across * across) + g.round_end : std::abs(across);
    cells[column] = std::max(cells[column], mask_of(std::clamp(g.h + 0.5 - distance, 0.0, 1.0)));
  }
}

#if defined(__x86_64__)
/// Cells [column, column + 4) raised to the masks of four coverages
/// (mask_of's float rounding), those past `last` (at most 3, which Coverage
/// keeps room for) left as they were.
[[gnu::target("avx2")]] inline void raise_cells(std::uint8_t* cells, int column, int last, __m256d coverage) {
  const __m128 scaled = _mm_mul_ps(_mm256_cvtpd_ps(coverage), _mm_set1_ps(255));
  const __m128i masks = _mm_cvttps_epi32(_mm_add_ps(scaled, _mm_set1_ps(0.5f)));
  const __m128i bytes = _mm_packus_epi16(_mm_packus_epi32(masks, masks), _mm_setzero_si128());
  const int valid = std::min(4, last - column + 1);
  const std::uint32_t keep = valid == 4 ? 0xffffffffu : (std::uint32_t(1) << (8 * valid)) - 1;
  std::uint32_t old_cells;
  std::memcpy(&old_cells, cells + column, 4);
  const __m128i ours = _mm_and_si128(bytes, _mm_cvtsi32_si128(int(keep)));
  const __m128i raised = _mm_max_epu8(ours, _mm_cvtsi32_si128(int(old_cells)));
  const auto merged = static_cast<std::uint32_t>(_mm_cvtsi128_si32(raised));
  std::memcpy(cells + column, &merged, 4);
}

/// The same, four pixels at a time (the last group masked: most rows of a
/// curve's piece are a few pixels), with the same operations in the same
/// order (IEEE arithmetic, no fused multiply-add), so the same masks to the
/// bit: a fifth of a scene's drawing was this loop.
[[gnu::target("avx2")]] void cover_plain_row_avx2(const Piece& p, const PieceGeometry& g, int row, int first, int last,
                                                 std::uint8_t* cells) {
  const double py = row + 0.5 - p.a.y;
  const __m256d half = _mm256_set1_pd(0.5), ax = _mm256_set1_pd(p.a.x), ux = _mm256_set1_pd(g.ux),
                uy = _mm256_set1_pd(g.uy), py_uy = _mm256_set1_pd(py * g.uy), py_ux = _mm256_set1_pd(py * g.ux),
                zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1), length = _mm256_set1_pd(g.length),
                round_end = _mm256_set1_pd(g.round_end), edge = _mm256_set1_pd(g.h + 0.5),
                sign = _mm256_set1_pd(-0.0);
  for (int column = first; column <= last; column += 4) {
    const __m256d px = _mm256_sub_pd(_mm256_add_pd(_mm256_cvtepi32_pd(_mm_setr_epi32(column, column + 1, column + 2, column + 3)), half), ax);
    const __m256d along = _mm256_add_pd(_mm256_mul_pd(px, ux), py_uy);
    const __m256d across = _mm256_sub_pd(_mm256_mul_pd(px, uy), py_ux);
    const __m256d beyond = _mm256_max_pd(_mm256_max_pd(zero, _mm256_xor_pd(along, sign)), _mm256_sub_pd(along, length));
    const __m256d round = _mm256_add_pd(
        _mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(beyond, beyond), _mm256_mul_pd(across, across))), round_end);
    const __m256d distance = _mm256_blendv_pd(_mm256_andnot_pd(sign, across), round, _mm256_cmp_pd(beyond, zero, _CMP_GT_OQ));
    const __m256d coverage = _mm256_min_pd(_mm256_max_pd(_mm256_sub_pd(edge, distance), zero), one);
    raise_cells(cells, column, last, coverage);
  }
}
#endif

using CoverRow = void (*)(const Piece&, const PieceGeometry&, int, int, int, std::uint8_t*);

/// The AVX2 loop where the processor has it, else the scalar one (the same bytes either way).
template <class Loop>
Loop fastest([[maybe_unused]] Loop avx2, Loop scalar) {
#if defined(__x86_64__)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2")) return avx2;
#endif
  return scalar;
}

/// One row's pixels of a piece with a cut end or a fence (see cover_plain_row_scalar).
void cover_cut_row_scalar(const Piece& p, const PieceGeometry& g, int row, int first, int last, std::uint8_t* cells) {
  const double cy = row + 0.5, py = cy - p.a.y;
  auto fence_at = [&](const Fence& f, double px) {
    return f.up ? (px - f.at.x) * f.dir.x + (cy - f.at.y) * f.dir.y + 0.5 : 1e300;
  };
  for (int column = first; column <= last; ++column) {
    const double px = column + 0.5 - p.a.x;
    const double along = px * g.ux + py * g.uy, across = px * g.uy - py * g.ux;
    const double inside_start = fence_at(p.start, column + 0.5), inside_end = fence_at(p.end, column + 0.5);
    double distance = std::abs(across), end = 1;
    if (along < 0) {
      if (p.cut_a) end = along + 0.5;
      else distance = std::sqrt(along * along + across * across) + g.round_end, end = std::min(inside_start, inside_end);
    } else if (along > g.length) {
      if (p.cut_b) end = g.length - along + 0.5;
      else distance = std::sqrt((along - g.length) * (along - g.length) + across * across) + g.round_end,
           end = std::min(inside_start, inside_end);
    }
    if (p.cut_a && along < 0.5) end = std::min(end, along + 0.5);
    if (p.cut_b && along > g.length - 0.5) end = std::min(end, g.length - along + 0.5);
    const double value = std::clamp(g.h + 0.5 - distance, 0.0, 1.0) * std::clamp(end, 0.0, 1.0);
    cells[column] = std::max(cells[column], mask_of(value));
  }
}

#if defined(__x86_64__)
/// A fence's (x - at.x) dir.x + (cy - at.y) dir.y + 0.5 at four pixel centres x, or 1e300 where it is down.
[[gnu::target("avx2")]] inline __m256d fence_at(const Fence& f, double cy, __m256d x) {
  if (!f.up) return _mm256_set1_pd(1e300);
  const __m256d across_rows = _mm256_set1_pd((cy - f.at.y) * f.dir.y);
  return _mm256_add_pd(
      _mm256_add_pd(_mm256_mul_pd(_mm256_sub_pd(x, _mm256_set1_pd(f.at.x)), _mm256_set1_pd(f.dir.x)), across_rows),
      _mm256_set1_pd(0.5));
}

/// std::clamp(v, 0.0, 1.0) lane by lane: v < 0 ? 0 : 1 < v ? 1 : v.
[[gnu::target("avx2")]] inline __m256d clamp01(__m256d v) {
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1);
  return _mm256_blendv_pd(_mm256_blendv_pd(v, one, _mm256_cmp_pd(one, v, _CMP_LT_OQ)), zero,
                          _mm256_cmp_pd(v, zero, _CMP_LT_OQ));
}

/// The same, four pixels at a time, each branch of the scalar loop a blend
/// of its lanes, with the same operations in the same order: the same masks
/// to the bit (std::min(a, b) is b < a ? b : a, _mm256_min_pd(b, a)). The
/// pieces with cut ends are a dashed line's: a comparison's ghost outlines.
[[gnu::target("avx2")]] void cover_cut_row_avx2(const Piece& p, const PieceGeometry& g, int row, int first, int last,
                                               std::uint8_t* cells) {
  const double cy = row + 0.5, py = cy - p.a.y;
  const __m256d half = _mm256_set1_pd(0.5), ax = _mm256_set1_pd(p.a.x), ux = _mm256_set1_pd(g.ux),
                uy = _mm256_set1_pd(g.uy), py_uy = _mm256_set1_pd(py * g.uy), py_ux = _mm256_set1_pd(py * g.ux),
                zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1), length = _mm256_set1_pd(g.length),
                round_end = _mm256_set1_pd(g.round_end), edge = _mm256_set1_pd(g.h + 0.5),
                sign = _mm256_set1_pd(-0.0), length_less_half = _mm256_set1_pd(g.length - 0.5);
  for (int column = first; column <= last; column += 4) {
    const __m128i columns = _mm_setr_epi32(column, column + 1, column + 2, column + 3);
    const __m256d centre = _mm256_add_pd(_mm256_cvtepi32_pd(columns), half);
    const __m256d px = _mm256_sub_pd(centre, ax);
    const __m256d along = _mm256_add_pd(_mm256_mul_pd(px, ux), py_uy);
    const __m256d across = _mm256_sub_pd(_mm256_mul_pd(px, uy), py_ux);
    const __m256d fences = _mm256_min_pd(fence_at(p.end, cy, centre), fence_at(p.start, cy, centre));
    const __m256d across2 = _mm256_mul_pd(across, across);
    __m256d distance = _mm256_andnot_pd(sign, across), end = one;
    const __m256d before = _mm256_cmp_pd(along, zero, _CMP_LT_OQ);
    const __m256d beyond = _mm256_andnot_pd(before, _mm256_cmp_pd(along, length, _CMP_GT_OQ));
    if (p.cut_a) {
      end = _mm256_blendv_pd(end, _mm256_add_pd(along, half), before);
    } else {
      const __m256d squared = _mm256_add_pd(_mm256_mul_pd(along, along), across2);
      const __m256d round = _mm256_add_pd(_mm256_sqrt_pd(squared), round_end);
      distance = _mm256_blendv_pd(distance, round, before);
      end = _mm256_blendv_pd(end, fences, before);
    }
    const __m256d past = _mm256_sub_pd(along, length);
    if (p.cut_b) {
      end = _mm256_blendv_pd(end, _mm256_add_pd(_mm256_sub_pd(length, along), half), beyond);
    } else {
      const __m256d round = _mm256_add_pd(_mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(past, past), across2)), round_end);
      distance = _mm256_blendv_pd(distance, round, beyond);
      end = _mm256_blendv_pd(end, fences, beyond);
    }
    if (p.cut_a)
      end = _mm256_blendv_pd(end, _mm256_min_pd(_mm256_add_pd(along, half), end),
                             _mm256_cmp_pd(along, half, _CMP_LT_OQ));
    if (p.cut_b)
      end = _mm256_blendv_pd(end, _mm256_min_pd(_mm256_add_pd(_mm256_sub_pd(length, along), half), end),
                             _mm256_cmp_pd(along, length_less_half, _CMP_GT_OQ));
    const __m256d value = _mm256_mul_pd(clamp01(_mm256_sub_pd(edge, distance)), clamp01(end));
    raise_cells(cells, column, last, value);
  }
}
#endif

/// The row loop for a piece: plain or cut, vector or scalar.
CoverRow cover_row_for(bool plain, bool scalar) {
  static const CoverRow plain_row = fastest<CoverRow>(AVX2_OR_NULL(cover_plain_row_avx2), cover_plain_row_scalar);
  static const CoverRow cut_row = fastest<CoverRow>(AVX2_OR_NULL(cover_cut_row_avx2), cover_cut_row_scalar);
  if (scalar) return plain ? cover_plain_row_scalar : cover_cut_row_scalar;
  return plain ? plain_row : cut_row;
}

/// Raises each pixel's coverage to the piece's: one minus how far the pixel's
/// centre is beyond the line's edge, within a pixel; at a cut end, times how
/// far the centre is inside the cut, within a pixel.
void cover(const Piece& p, const Plan& plan, Coverage& coverage) {
  const int width = plan.x1 - plan.x0;
  const PieceGeometry g(p, plan.half_width);
  const bool plain = !p.cut_a && !p.cut_b && !p.start.up && !p.end.up;
  const CoverRow cover_row = cover_row_for(plain, plan.scalar);
  // Pixel centres (row + 0.5) within reach of the segment's rows; none when it is beyond the clip.
  const int row_first = ceil_within(std::min(p.a.y, p.b.y) - g.reach - 0.5, plan.y0, plan.y1);
  const int row_last = floor_within(std::max(p.a.y, p.b.y) + g.reach - 0.5, plan.y0 - 1, plan.y1 - 1);
  const int box_first = ceil_within(std::min(p.a.x, p.b.x) - g.reach - 0.5, plan.x0, plan.x1);
  const int box_last = floor_within(std::max(p.a.x, p.b.x) + g.reach - 0.5, plan.x0 - 1, plan.x1 - 1);
  // A short piece (most of a curve's) covers most of its box: every pixel of
  // it is tried; a long one only its stretch of each row.
  const bool short_piece = g.length <= 4 * g.reach;
  for (int row = row_first; row <= row_last; ++row) {
    int first = box_first, last = box_last;
    if (!short_piece && !long_piece_columns(p, g, plan, row, first, last)) continue;
    if (first > last) continue;
    const int r = row - plan.y0;
    std::uint8_t* cells = coverage.cells.data() + std::size_t(r) * width - plan.x0;
    coverage.touch(r, first, last);
    cover_row(p, g, row, first, last, cells);
  }
}

void blend(const Plan& plan, Coverage& coverage, cairo_surface_t* target) {
  unsigned char* data = cairo_image_surface_get_data(target);
  const int stride = cairo_image_surface_get_stride(target), width = plan.x1 - plan.x0;
  for (int r = coverage.first_row; r <= coverage.last_row; ++r) {
    if (coverage.lo[r] > coverage.hi[r]) continue;
    std::uint8_t* cells = coverage.cells.data() + std::size_t(r) * width - plan.x0;
    auto* row = reinterpret_cast<std::uint32_t*>(data + std::ptrdiff_t(r + plan.y0) * stride);
    blend_span(row, cells, coverage.lo[r], coverage.hi[r], plan.source, plan.scalar);
    coverage.lo[r] = INT_MAX, coverage.hi[r] = INT_MIN;
  }
  coverage.first_row = INT_MAX, coverage.last_row = INT_MIN;
}

void blend_span_scalar(std::uint32_t* pixels, std::uint8_t* masks, int first, int last, std::uint32_t source) {
  for (int column = first; column <= last; ++column) {
    const std::uint32_t mask = masks[column];
    if (mask == 0) continue;  // a gap between the stroke's parts in this row
    masks[column] = 0;
    // Source IN mask OVER destination.
    const std::uint32_t in = times_alpha(source, mask);
    pixels[column] = in + times_alpha(pixels[column], 255 - (in >> 24));
  }
}

#if defined(__x86_64__)
/// times_alpha on eight pixels, with their own alphas.
[[gnu::target("avx2")]] inline __m256i times_alpha8(__m256i x, __m256i a) {
  const __m256i low = _mm256_set1_epi32(0xff00ff), bias = _mm256_set1_epi32(0x800080);
  __m256i rb = _mm256_add_epi32(_mm256_mullo_epi32(_mm256_and_si256(x, low), a), bias);
  rb = _mm256_add_epi32(rb, _mm256_and_si256(_mm256_srli_epi32(rb, 8), low));
  rb = _mm256_and_si256(_mm256_srli_epi32(rb, 8), low);
  __m256i ag = _mm256_add_epi32(_mm256_mullo_epi32(_mm256_and_si256(_mm256_srli_epi32(x, 8), low), a), bias);
  ag = _mm256_and_si256(_mm256_add_epi32(ag, _mm256_and_si256(_mm256_srli_epi32(ag, 8), low)),
                        _mm256_set1_epi32(int(0xff00ff00u)));
  return _mm256_or_si256(rb, ag);
}

/// The same eight pixels at a time. A mask of 0 leaves its pixel as it was,
/// as the scalar loop's skip does: times_alpha(p, 255) is p exactly.
[[gnu::target("avx2")]] void blend_span_avx2(std::uint32_t* pixels, std::uint8_t* masks, int first, int last,
                                            std::uint32_t source) {
  const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7), full = _mm256_set1_epi32(255),
                colour = _mm256_set1_epi32(int(source));
  for (int column = first; column <= last; column += 8) {
    const int valid = std::min(8, last - column + 1);
    const __m256i inside = _mm256_cmpgt_epi32(_mm256_set1_epi32(valid), lanes);
    std::uint64_t mask_bytes;
    std::memcpy(&mask_bytes, masks + column, 8);
    const __m256i mask = _mm256_and_si256(_mm256_cvtepu8_epi32(_mm_cvtsi64_si128(std::int64_t(mask_bytes))), inside);
    auto* at = reinterpret_cast<int*>(pixels + column);
    const __m256i in = times_alpha8(colour, mask);
    const __m256i out = _mm256_add_epi32(in, times_alpha8(_mm256_maskload_epi32(at, inside),
                                                           _mm256_sub_epi32(full, _mm256_srli_epi32(in, 24))));
    _mm256_maskstore_epi32(at, inside, out);
    mask_bytes = valid == 8 ? 0 : mask_bytes & (~std::uint64_t(0) << (8 * valid));
    std::memcpy(masks + column, &mask_bytes, 8);
  }
}
#endif

using BlendSpan = void (*)(std::uint32_t*, std::uint8_t*, int, int, std::uint32_t);

}  // namespace

void blend_span(std::uint32_t* pixels, std::uint8_t* masks, int first, int last, std::uint32_t source,
                bool one_at_a_time) {
  static const BlendSpan loop = fastest<BlendSpan>(AVX2_OR_NULL(blend_span_avx2), blend_span_scalar);
  (one_at_a_time ? blend_span_scalar : loop)(pixels, masks, first, last, source);
}

double stroked_distance(double ax, double ay, double bx, double by) {
  auto fixed = [](double v) { return std::nearbyint(v * 256) / 256; };
  return std::hypot(fixed(bx) - fixed(ax), fixed(by) - fixed(ay));
}

bool raster_stroke(cairo_t* cr, bool scalar) {
  cairo_surface_t* target = cairo_get_group_target(cr);
  Plan plan;
  if (!plan_stroke(cr, target, plan)) return false;
  plan.scalar = scalar;
  cairo_new_path(cr);
  if (plan.x1 <= plan.x0 || plan.y1 <= plan.y0 || plan.pieces.empty()) return true;
  thread_local Coverage coverage;
  coverage.prepare(plan.x1 - plan.x0, plan.y1 - plan.y0);
  for (const Piece& p : plan.pieces) cover(p, plan, coverage);
  cairo_surface_flush(target);
  blend(plan, coverage, target);
  cairo_surface_mark_dirty(target);
  return true;
}

}  // namespace vibra::render
