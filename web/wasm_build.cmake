# The browser build (web/) as a step of the main build: configured with emscripten's toolchain when em++ is installed.
# Optional: without emscripten (or with VIBRA_WEB=OFF) the native build and its
# tests are unchanged, and the tests of the browser build are skipped saying so.
find_program(VIBRA_EMCMAKE emcmake)
find_program(VIBRA_CCACHE ccache)
if(VIBRA_EMCMAKE AND NOT VIBRA_SANITIZE AND NOT VIBRA_FUZZ)
  set(VIBRA_WEB_DEFAULT ON)
else()
  set(VIBRA_WEB_DEFAULT OFF)
endif()
option(VIBRA_WEB "Build the core as WebAssembly for the browser (web/, needs emscripten)" ${VIBRA_WEB_DEFAULT})
set(VIBRA_WEB_DIR ${CMAKE_CURRENT_BINARY_DIR}/web)
if(VIBRA_WEB)
  if(NOT VIBRA_EMCMAKE)
    message(FATAL_ERROR "VIBRA_WEB needs emscripten: apt-get install emscripten, or configure with -DVIBRA_WEB=OFF")
  endif()
  include(ExternalProject)
  # emcc's JavaScript tools need Debian's acorn even under a node of another origin.
  set(VIBRA_EM_ENV ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs)
  set(VIBRA_WEB_LAUNCHER "")
  if(VIBRA_CCACHE)
    set(VIBRA_WEB_LAUNCHER -DCMAKE_CXX_COMPILER_LAUNCHER=${VIBRA_CCACHE})
  endif()
  ExternalProject_Add(vibra_web
    SOURCE_DIR ${CMAKE_CURRENT_SOURCE_DIR}/web
    BINARY_DIR ${VIBRA_WEB_DIR}
    CONFIGURE_COMMAND ${VIBRA_EM_ENV} ${VIBRA_EMCMAKE} ${CMAKE_COMMAND} -S <SOURCE_DIR> -B <BINARY_DIR> -G Ninja
                      -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=${CMAKE_UNITY_BUILD} ${VIBRA_WEB_LAUNCHER}
    BUILD_COMMAND ${VIBRA_EM_ENV} ${CMAKE_COMMAND} --build <BINARY_DIR>
    INSTALL_COMMAND ""
    BUILD_ALWAYS ON
    USES_TERMINAL_BUILD ON)
endif()

# The live page's files, where `vibra render --live` finds them (build/live/,
# beside the executable; installed in share/vibra/live/): the module, the
# page's script and style, and the fonts the scene code measures with.
# The fonts are Debian's DejaVu files, the ones Pango draws with natively.
set(VIBRA_DEJAVU_DIR /usr/share/fonts/truetype/dejavu)
set(VIBRA_LIVE_DIR ${CMAKE_CURRENT_BINARY_DIR}/live)
if(VIBRA_WEB)
  set(VIBRA_LIVE_SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/web/canvas/replay.js ${CMAKE_CURRENT_SOURCE_DIR}/web/page/live.js
      ${CMAKE_CURRENT_SOURCE_DIR}/web/page/live.css ${CMAKE_CURRENT_SOURCE_DIR}/web/page/live.html.in
      ${VIBRA_DEJAVU_DIR}/DejaVuSans.ttf ${VIBRA_DEJAVU_DIR}/DejaVuSans-Oblique.ttf ${VIBRA_DEJAVU_DIR}/DejaVuSans-Bold.ttf
      ${VIBRA_DEJAVU_DIR}/DejaVuSans-BoldOblique.ttf)
  add_custom_target(vibra_live_assets ALL
    COMMAND ${CMAKE_COMMAND} -E make_directory ${VIBRA_LIVE_DIR}
    COMMAND ${CMAKE_COMMAND} -E copy_if_different ${VIBRA_LIVE_SOURCES} ${VIBRA_WEB_DIR}/vibra_live.js ${VIBRA_LIVE_DIR}
    DEPENDS vibra_web ${VIBRA_LIVE_SOURCES}
    COMMENT "The live page's files in ${VIBRA_LIVE_DIR}")
  install(DIRECTORY ${VIBRA_LIVE_DIR}/ DESTINATION ${CMAKE_INSTALL_DATADIR}/vibra/live)
endif()
