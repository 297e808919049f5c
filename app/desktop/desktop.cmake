# The desktop window of swarmlab: Dear ImGui 1.86 over SDL2 + OpenGL 3.3, all from Debian
# (libimgui-dev holds the SDL2 and OpenGL3 backends in libimgui.a). Included by
# app/CMakeLists.txt when present; adds its sources to the existing target `swarmlab`.
find_package(PkgConfig REQUIRED)
pkg_check_modules(SWARMLAB_SDL2 REQUIRED IMPORTED_TARGET sdl2)
find_package(OpenGL REQUIRED)
find_library(SWARMLAB_IMGUI_LIB imgui REQUIRED)
find_library(SWARMLAB_STB_LIB stb REQUIRED)
find_path(SWARMLAB_IMGUI_INCLUDE imgui.h PATH_SUFFIXES imgui REQUIRED)
find_path(SWARMLAB_STB_INCLUDE stb_image_write.h PATH_SUFFIXES stb REQUIRED)

# The UI font is compiled into the binary so that the web build needs no font file either.
set(SWARMLAB_FONT_TTF "${PROJECT_SOURCE_DIR}/assets/fonts/DejaVuSans.ttf")
set(SWARMLAB_FONT_CPP "${CMAKE_CURRENT_BINARY_DIR}/generated/dejavu_sans_ttf.cpp")
add_custom_command(
  OUTPUT "${SWARMLAB_FONT_CPP}"
  COMMAND ${CMAKE_COMMAND} -DINPUT=${SWARMLAB_FONT_TTF} -DOUTPUT=${SWARMLAB_FONT_CPP}
          -DSYMBOL=dejavu_sans_ttf -P ${CMAKE_CURRENT_LIST_DIR}/embed_file.cmake
  DEPENDS "${SWARMLAB_FONT_TTF}" "${CMAKE_CURRENT_LIST_DIR}/embed_file.cmake"
  COMMENT "Embedding DejaVuSans.ttf")

set(SWARMLAB_DESKTOP_DIR "${CMAKE_CURRENT_LIST_DIR}")
target_sources(swarmlab PRIVATE
  ${SWARMLAB_DESKTOP_DIR}/app.cpp
  ${SWARMLAB_DESKTOP_DIR}/app_state.cpp
  ${SWARMLAB_DESKTOP_DIR}/camera.cpp
  ${SWARMLAB_DESKTOP_DIR}/colour_map.cpp
  ${SWARMLAB_DESKTOP_DIR}/desktop.cpp
  ${SWARMLAB_DESKTOP_DIR}/fonts.cpp
  ${SWARMLAB_DESKTOP_DIR}/live_run.cpp
  ${SWARMLAB_DESKTOP_DIR}/main_loop.cpp
  ${SWARMLAB_DESKTOP_DIR}/panels_container.cpp
  ${SWARMLAB_DESKTOP_DIR}/panels_plots.cpp
  ${SWARMLAB_DESKTOP_DIR}/panels_scenario.cpp
  ${SWARMLAB_DESKTOP_DIR}/panels_simulation.cpp
  ${SWARMLAB_DESKTOP_DIR}/panels_system.cpp
  ${SWARMLAB_DESKTOP_DIR}/panels_view.cpp
  ${SWARMLAB_DESKTOP_DIR}/particle_renderer.cpp
  ${SWARMLAB_DESKTOP_DIR}/plot_widget.cpp
  ${SWARMLAB_DESKTOP_DIR}/preset_store_files.cpp
  ${SWARMLAB_DESKTOP_DIR}/readouts.cpp
  ${SWARMLAB_DESKTOP_DIR}/scene_overlay.cpp
  ${SWARMLAB_DESKTOP_DIR}/screenshot.cpp
  ${SWARMLAB_DESKTOP_DIR}/shaders.cpp
  ${SWARMLAB_DESKTOP_DIR}/shortcuts.cpp
  ${SWARMLAB_DESKTOP_DIR}/sdl_window.cpp
  "${SWARMLAB_FONT_CPP}")
target_include_directories(swarmlab PRIVATE
  "${CMAKE_CURRENT_SOURCE_DIR}" ${SWARMLAB_IMGUI_INCLUDE} ${SWARMLAB_STB_INCLUDE})
target_compile_definitions(swarmlab PRIVATE
  SWARMLAB_HAS_DESKTOP
  SWARMLAB_PRESET_DIR="${PROJECT_SOURCE_DIR}/assets/presets")
target_link_libraries(swarmlab PRIVATE
  ${SWARMLAB_IMGUI_LIB} ${SWARMLAB_STB_LIB} PkgConfig::SWARMLAB_SDL2 OpenGL::GL ${CMAKE_DL_LIBS})
