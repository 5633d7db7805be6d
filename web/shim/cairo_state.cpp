// The browser build's Cairo contexts: creation, save and restore, groups, the source, the pen and the user matrix.
#include <cmath>

#include "web/shim/cairo_context.hpp"

namespace vibra::web::shim {

DevicePoint to_device(const cairo_t* cr, double x, double y) {
  const auto& m = cr->state.pen.matrix;  // xx yx xy yy x0 y0
  return {m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5]};
}

DevicePoint to_user(const cairo_t* cr, double x, double y) {
  const auto& m = cr->state.pen.matrix;
  const double det = m[0] * m[3] - m[1] * m[2];
  const double dx = x - m[4], dy = y - m[5];
  return {(m[3] * dx - m[2] * dy) / det, (m[0] * dy - m[1] * dx) / det};
}

}  // namespace vibra::web::shim

using vibra::web::shim::commands;

extern "C" {

cairo_t* cairo_create(cairo_surface_t* target) {
  ++target->references;
  auto* cr = new _cairo;
  cr->target = target;
  return cr;
}

void cairo_destroy(cairo_t* cr) {
  if (!cr) return;
  cairo_surface_destroy(cr->target);
  delete cr;
}

cairo_status_t cairo_status(cairo_t* cr) { return cr->status; }

void cairo_save(cairo_t* cr) {
  cr->saved.push_back(cr->state);
  commands(cr).save();
}

void cairo_restore(cairo_t* cr) {
  if (cr->saved.empty() || (!cr->group_depths.empty() && cr->saved.size() == cr->group_depths.back())) {
    cr->status = CAIRO_STATUS_INVALID_RESTORE;
    return;
  }
  cr->state = cr->saved.back();
  cr->saved.pop_back();
  commands(cr).restore();
}

// A group is a layer of the page's canvas: what is drawn until the pop goes
// there, and the paint that follows lays it on the canvas below.
void cairo_push_group(cairo_t* cr) {
  cr->saved.push_back(cr->state);
  cr->group_depths.push_back(cr->saved.size());
  commands(cr).push_group();
}

void cairo_pop_group_to_source(cairo_t* cr) {
  if (cr->group_depths.empty()) {
    cr->status = CAIRO_STATUS_INVALID_POP_GROUP;
    return;
  }
  cr->saved.resize(cr->group_depths.back());
  cr->group_depths.pop_back();
  cr->state = cr->saved.back();
  cr->saved.pop_back();
  cr->state.group_source = true;
}

cairo_surface_t* cairo_get_group_target(cairo_t* cr) { return cr->target; }

void cairo_set_source_rgba(cairo_t* cr, double r, double g, double b, double a) {
  cr->state.source = _cairo_pattern{CAIRO_PATTERN_TYPE_SOLID, {r, g, b, a}};
  cr->state.pen.rgba = {r, g, b, a};
  cr->state.group_source = false;
}
void cairo_set_source_rgb(cairo_t* cr, double r, double g, double b) { cairo_set_source_rgba(cr, r, g, b, 1); }

void cairo_set_source(cairo_t* cr, cairo_pattern_t* source) {
  cr->state.source = *source;
  cr->state.source_user = cr->state.pen.matrix;
  cr->state.pen.rgba = source->rgba;
  cr->state.group_source = false;
}

void cairo_set_source_surface(cairo_t* cr, cairo_surface_t* surface, double x, double y) {
  _cairo_pattern pattern{CAIRO_PATTERN_TYPE_SURFACE, {0, 0, 0, 0}, surface};
  pattern.matrix = {1, 0, 0, 1, -x, -y};  // the surface's origin at (x, y)
  cairo_set_source(cr, &pattern);
}

cairo_pattern_t* cairo_get_source(cairo_t* cr) { return &cr->state.source; }

void cairo_set_operator(cairo_t* cr, cairo_operator_t op) {
  cr->state.op = op;
  commands(cr).composite(op);
}
cairo_operator_t cairo_get_operator(cairo_t* cr) { return cr->state.op; }
void cairo_set_antialias(cairo_t* cr, cairo_antialias_t a) { cr->state.antialias = a; }
cairo_antialias_t cairo_get_antialias(cairo_t* cr) { return cr->state.antialias; }
void cairo_set_line_width(cairo_t* cr, double width) { cr->state.pen.width = width; }
double cairo_get_line_width(cairo_t* cr) { return cr->state.pen.width; }
void cairo_set_line_join(cairo_t* cr, cairo_line_join_t join) { cr->state.pen.join = join; }
cairo_line_join_t cairo_get_line_join(cairo_t* cr) { return cairo_line_join_t(cr->state.pen.join); }
void cairo_set_line_cap(cairo_t* cr, cairo_line_cap_t cap) { cr->state.pen.cap = cap; }
cairo_line_cap_t cairo_get_line_cap(cairo_t* cr) { return cairo_line_cap_t(cr->state.pen.cap); }

void cairo_set_dash(cairo_t* cr, const double* dashes, int num_dashes, double offset) {
  cr->state.pen.dashes.assign(dashes, dashes + (num_dashes > 0 ? num_dashes : 0));
  cr->state.pen.dash_offset = offset;
}
int cairo_get_dash_count(cairo_t* cr) { return static_cast<int>(cr->state.pen.dashes.size()); }
void cairo_get_dash(cairo_t* cr, double* dashes, double* offset) {
  for (std::size_t i = 0; dashes && i < cr->state.pen.dashes.size(); ++i) dashes[i] = cr->state.pen.dashes[i];
  if (offset) *offset = cr->state.pen.dash_offset;
}

void cairo_translate(cairo_t* cr, double tx, double ty) {
  auto& m = cr->state.pen.matrix;
  m[4] += m[0] * tx + m[2] * ty;
  m[5] += m[1] * tx + m[3] * ty;
}
void cairo_identity_matrix(cairo_t* cr) { cr->state.pen.matrix = {1, 0, 0, 1, 0, 0}; }
void cairo_get_matrix(cairo_t* cr, cairo_matrix_t* out) {
  const auto& m = cr->state.pen.matrix;
  *out = cairo_matrix_t{m[0], m[1], m[2], m[3], m[4], m[5]};
}
void cairo_matrix_init_translate(cairo_matrix_t* m, double tx, double ty) { *m = cairo_matrix_t{1, 0, 0, 1, tx, ty}; }

void cairo_user_to_device(cairo_t* cr, double* x, double* y) {
  const auto p = vibra::web::shim::to_device(cr, *x, *y);
  *x = p.x, *y = p.y;
}
void cairo_user_to_device_distance(cairo_t* cr, double* dx, double* dy) {
  const auto& m = cr->state.pen.matrix;
  const double x = *dx, y = *dy;
  *dx = m[0] * x + m[2] * y, *dy = m[1] * x + m[3] * y;
}
void cairo_device_to_user(cairo_t* cr, double* x, double* y) {
  const auto p = vibra::web::shim::to_user(cr, *x, *y);
  *x = p.x, *y = p.y;
}

}  // extern "C"
