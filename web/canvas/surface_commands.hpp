// What a surface of the browser build recorded: its operations for the page, and what it could not hand over.
#pragma once
#include <cairo.h>

#include "web/canvas/draw_commands.hpp"

namespace vibra::web {

/// The operations drawn on `surface` since the last take (a frame's).
DrawCommands& commands_of(cairo_surface_t* surface);
/// How many drawing operations had a surface as their source: the 2D
/// canvas is not handed those (the scene code takes image-only paths there).
int skipped_of(cairo_surface_t* surface);

}  // namespace vibra::web
