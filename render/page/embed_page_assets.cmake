# Writes OUTPUT: a C++ file defining page_asset(name) from the page's files
# in PAGE_DIR and uPlot's in UPLOT_DIR, each embedded as a raw string under
# its file name, so pages are written from any directory and need no network.
set(body "")
foreach(asset "${PAGE_DIR}/lecture.html.in" "${PAGE_DIR}/page.js" "${PAGE_DIR}/page.css"
              "${PAGE_DIR}/present.html.in" "${PAGE_DIR}/present.js" "${PAGE_DIR}/present.css"
              "${UPLOT_DIR}/uPlot.iife.min.js" "${UPLOT_DIR}/uPlot.min.css")
  get_filename_component(name "${asset}" NAME)
  file(READ "${asset}" text)
  string(FIND "${text}" ")vibra_asset\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${asset} contains the raw-string delimiter )vibra_asset\"")
  endif()
  string(APPEND body "  if (name == \"${name}\") return R\"vibra_asset(${text})vibra_asset\";\n")
endforeach()
file(WRITE "${OUTPUT}.new" "// Generated from render/page/ and third_party/uplot/ by render/page/embed_page_assets.cmake: do not edit.
#include \"render/page/page_assets.hpp\"

#include <stdexcept>

namespace vibra::render {
std::string_view page_asset(std::string_view name) {
${body}  throw std::logic_error(\"no page asset named \" + std::string(name));
}
}  // namespace vibra::render
")
file(COPY_FILE "${OUTPUT}.new" "${OUTPUT}" ONLY_IF_DIFFERENT)
