/* The browser build's <cairo-svg.h>: its surface is declared with the rest in web/shim/cairo.h. */
#pragma once
#include <cairo.h>
