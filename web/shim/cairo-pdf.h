/* The browser build's <cairo-pdf.h>: its surface is declared with the rest in web/shim/cairo.h. */
#pragma once
#include <cairo.h>
