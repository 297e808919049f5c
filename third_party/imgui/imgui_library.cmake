# swarmlab_imgui(<imgui_dir>): the static library swarmlab_imgui, Dear ImGui 1.86 with its SDL2
# and OpenGL3 backends, compiled from the sources scripts/imgui-sources.sh unpacked and patched
# (patches/, README.md), with the item hooks on, for the desktop and the page alike (each adds
# its GL flavour and SDL2).
#
# The sources must carry the patches as they are now: the tree's stamp names each patch's
# SHA-256, and a patch edited since the tree was made stops the configure (rather than building
# an ImGui without a hook or with an old one). Editing a patch reconfigures.
function(swarmlab_imgui imgui_dir)
  set(patch_dir "${PROJECT_SOURCE_DIR}/third_party/imgui/patches")
  file(GLOB patches RELATIVE "${patch_dir}" "${patch_dir}/*.patch")
  list(SORT patches)
  set(wanted "")
  foreach(patch IN LISTS patches)
    file(SHA256 "${patch_dir}/${patch}" sum)
    string(APPEND wanted "${sum}  ${patch}\n")
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${patch_dir}/${patch}")
  endforeach()
  set(stamp "${imgui_dir}/.stamp-v2")
  set(found "")
  if(EXISTS "${stamp}")
    file(READ "${stamp}" found)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${stamp}")
  endif()
  # Its first line names Debian's source package; then one line per patch.
  string(FIND "${found}" "\n" first_line_end)
  math(EXPR sums_begin "${first_line_end} + 1")
  string(SUBSTRING "${found}" ${sums_begin} -1 found)
  if(NOT found STREQUAL wanted)
    message(FATAL_ERROR "The ImGui sources in ${imgui_dir} do not carry third_party/imgui/patches "
                        "as they are now: run scripts/imgui-sources.sh (scripts/build.sh and "
                        "scripts/web-deps.sh do)")
  endif()
  add_library(swarmlab_imgui STATIC
    ${imgui_dir}/imgui.cpp ${imgui_dir}/imgui_draw.cpp ${imgui_dir}/imgui_tables.cpp
    ${imgui_dir}/imgui_widgets.cpp ${imgui_dir}/misc/cpp/imgui_stdlib.cpp
    ${imgui_dir}/backends/imgui_impl_sdl.cpp ${imgui_dir}/backends/imgui_impl_opengl3.cpp)
  target_include_directories(swarmlab_imgui SYSTEM PUBLIC ${imgui_dir} ${imgui_dir}/backends ${imgui_dir}/misc/cpp)
  target_compile_definitions(swarmlab_imgui PUBLIC IMGUI_ENABLE_TEST_ENGINE)
endfunction()
