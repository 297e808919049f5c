# Dear ImGui 1.86's widgets, from Debian's sources, with the parallel DOM's value hook added
# where the stock item hooks (IMGUI_ENABLE_TEST_ENGINE) say too little for a screen reader:
# what a text or number field holds, a slider's value, whether a radio button or a list entry
# is selected, a combo's choice; and item info for the three widgets that report none
# (InvisibleButton, a window's close button, a combo). Later ImGui releases report most of
# these themselves. Each insertion is checked: a different ImGui stops the configure.
#   swarmlab_imgui_widgets_with_hooks(<imgui_dir> <out_var>): writes the patched copy into the
#   build tree and sets out_var to its path.
# (imgui.cpp, swarmlab_imgui_with_hooks below) An item scrolled out of its window is not drawn,
# so its label never reaches the hooks; an item the parallel DOM has not yet named is drawn
# once though out of sight (scissored away), so that a screen reader and Tab reach it too.

# Puts `replacement` where `anchor` stands in src (the caller's), which must hold it `expected` times.
function(_swarmlab_hook_edit anchor replacement expected)
  string(LENGTH "${src}" before)
  string(REPLACE "${anchor}" "@" probe "${src}")
  string(LENGTH "${probe}" after)
  string(LENGTH "${anchor}" alen)
  math(EXPR count "(${before} - ${after}) / (${alen} - 1)")
  if(NOT count EQUAL expected)
    message(FATAL_ERROR "imgui_hooks.cmake: expected ${expected} of this text in imgui_widgets.cpp, found ${count}:\n${anchor}")
  endif()
  string(REPLACE "${anchor}" "${replacement}" src "${src}")
  set(src "${src}" PARENT_SCOPE)
endfunction()

function(swarmlab_imgui_widgets_with_hooks imgui_dir out_var)
  file(READ "${imgui_dir}/imgui_widgets.cpp" src)
  set(out "${CMAKE_CURRENT_BINARY_DIR}/generated/imgui_widgets_with_hooks.cpp")
  set(hook "ParallelDomHook_ItemValue")
  _swarmlab_hook_edit(
    "#include \"imgui_internal.h\"\n"
    "#include \"imgui_internal.h\"\nextern void ${hook}(ImGuiContext* ctx, ImGuiID id, int kind, const char* value);  // Swarm Lab: app/ui/parallel_dom\n"
    1)
  # RadioButton(label, bool active): 4 = radio, selected or not
  _swarmlab_hook_edit(
    "        RenderText(label_pos, label);\n\n    IMGUI_TEST_ENGINE_ITEM_INFO(id, label, g.LastItemData.StatusFlags);\n"
    "        RenderText(label_pos, label);\n\n    if (g.TestEngineHookItems) ${hook}(&g, id, 4, active ? \"1\" : \"0\");\n    IMGUI_TEST_ENGINE_ITEM_INFO(id, label, g.LastItemData.StatusFlags);\n"
    1)
  # InvisibleButton: its str_id is its name
  _swarmlab_hook_edit(
    "    bool pressed = ButtonBehavior(bb, id, &hovered, &held, flags);\n\n    return pressed;\n"
    "    bool pressed = ButtonBehavior(bb, id, &hovered, &held, flags);\n    if (GImGui->TestEngineHookItems) ImGuiTestEngineHook_ItemInfo(GImGui, id, str_id, GImGui->LastItemData.StatusFlags);\n\n    return pressed;\n"
    1)
  # A window's close button: named by the parallel DOM after its window
  _swarmlab_hook_edit(
    "    bool pressed = ButtonBehavior(bb_interact, id, &hovered, &held);\n"
    "    bool pressed = ButtonBehavior(bb_interact, id, &hovered, &held);\n    IMGUI_TEST_ENGINE_ITEM_INFO(id, \"#CLOSE\", g.LastItemData.StatusFlags);\n"
    1)
  # BeginCombo: 5 = combo, showing preview_value
  _swarmlab_hook_edit(
    "    if (!popup_open)\n        return false;\n\n    g.NextWindowData.Flags = backup_next_window_data_flags;\n"
    "    if (g.TestEngineHookItems) ${hook}(&g, id, 5, preview_value ? preview_value : \"\");\n    IMGUI_TEST_ENGINE_ITEM_INFO(id, label, g.LastItemData.StatusFlags | ImGuiItemStatusFlags_Openable | (popup_open ? ImGuiItemStatusFlags_Opened : 0));\n    if (!popup_open)\n        return false;\n\n    g.NextWindowData.Flags = backup_next_window_data_flags;\n"
    1)
  # InputTextEx: 1 = text, 2 = a number (decimal or scientific characters); never a password
  _swarmlab_hook_edit(
    "    IMGUI_TEST_ENGINE_ITEM_INFO(id, label, g.LastItemData.StatusFlags);\n    if ((flags & ImGuiInputTextFlags_EnterReturnsTrue) != 0)\n"
    "    if (g.TestEngineHookItems) ${hook}(&g, id, (flags & (ImGuiInputTextFlags_CharsDecimal | ImGuiInputTextFlags_CharsScientific)) ? 2 : 1, (flags & ImGuiInputTextFlags_Password) ? \"\" : buf);\n    IMGUI_TEST_ENGINE_ITEM_INFO(id, label, g.LastItemData.StatusFlags);\n    if ((flags & ImGuiInputTextFlags_EnterReturnsTrue) != 0)\n"
    1)
  # DragScalar and SliderScalar: 3 = slider, showing value_buf
  _swarmlab_hook_edit(
    "    IMGUI_TEST_ENGINE_ITEM_INFO(id, label, g.LastItemData.StatusFlags);\n    return value_changed;\n"
    "    if (g.TestEngineHookItems) ${hook}(&g, id, 3, value_buf);\n    IMGUI_TEST_ENGINE_ITEM_INFO(id, label, g.LastItemData.StatusFlags);\n    return value_changed;\n"
    2)
  # Selectable: 6 = a list entry, selected or not
  _swarmlab_hook_edit(
    "    IMGUI_TEST_ENGINE_ITEM_INFO(id, label, g.LastItemData.StatusFlags);\n    return pressed; //-V1020\n"
    "    if (g.TestEngineHookItems) ${hook}(&g, id, 6, selected ? \"1\" : \"0\");\n    IMGUI_TEST_ENGINE_ITEM_INFO(id, label, g.LastItemData.StatusFlags);\n    return pressed; //-V1020\n"
    1)

  # Not a hook: a field gives way to its label. A slider, drag, text or number field or a
  # combo with its label on the right is narrowed, where the row is too short for both, so
  # that the label shows whole (a translation's label is longer); never below 40% of the row
  # (a longer label is still cut off, and the parallel DOM says so). Where both fit, as in
  # English, nothing changes.
  _swarmlab_hook_edit(
    "extern void ${hook}(ImGuiContext* ctx, ImGuiID id, int kind, const char* value);  // Swarm Lab: app/ui/parallel_dom\n"
    "extern void ${hook}(ImGuiContext* ctx, ImGuiID id, int kind, const char* value);  // Swarm Lab: app/ui/parallel_dom\nstatic float SwarmlabRoomForLabel(float w, float label_w)  // Swarm Lab: the field gives way to its label\n{\n    ImGuiContext& g = *GImGui;\n    ImGuiWindow* window = g.CurrentWindow;\n    if (label_w <= 0.0f || w <= 0.0f)\n        return w;\n    const float row = window->WorkRect.Max.x - window->DC.CursorPos.x;\n    const float room = row - g.Style.ItemInnerSpacing.x - label_w;\n    return ImMin(w, ImMax(room, ImMin(w, ImMax(3.0f * g.FontSize, 0.4f * row))));\n}\n"
    1)
  # DragScalar, SliderScalar
  _swarmlab_hook_edit(
    "    const float w = CalcItemWidth();\n\n    const ImVec2 label_size = CalcTextSize(label, NULL, true);\n"
    "    const ImVec2 label_size = CalcTextSize(label, NULL, true);\n    const float w = SwarmlabRoomForLabel(CalcItemWidth(), label_size.x);\n"
    2)
  # BeginCombo
  _swarmlab_hook_edit(
    "    const float w = (flags & ImGuiComboFlags_NoPreview) ? arrow_size : CalcItemWidth();\n"
    "    const float w = (flags & ImGuiComboFlags_NoPreview) ? arrow_size : SwarmlabRoomForLabel(CalcItemWidth(), label_size.x);\n"
    1)
  # InputTextEx (a single line)
  _swarmlab_hook_edit(
    "    const ImVec2 frame_size = CalcItemSize(size_arg, CalcItemWidth(), (is_multiline"
    "    const ImVec2 frame_size = CalcItemSize(size_arg, is_multiline ? CalcItemWidth() : SwarmlabRoomForLabel(CalcItemWidth(), label_size.x), (is_multiline"
    1)
  # InputScalar with its - and + buttons
  _swarmlab_hook_edit(
    "        SetNextItemWidth(ImMax(1.0f, CalcItemWidth() - (button_size + style.ItemInnerSpacing.x) * 2));\n"
    "        SetNextItemWidth(ImMax(1.0f, SwarmlabRoomForLabel(CalcItemWidth(), CalcTextSize(label, NULL, true).x) - (button_size + style.ItemInnerSpacing.x) * 2));\n"
    1)

  # Not a hook: the language's decimal separator (app/i18n). ImGui 1.86 formats and reads
  # numbers with the C library in the "C" locale; Swarm Lab shows a float or double in a field
  # or on a slider with the context's PlatformLocaleDecimalPoint (',' in German) and reads a
  # typed '.' or ',' alike, in every language.
  _swarmlab_hook_edit(
    "int ImGui::DataTypeFormatString(char* buf, int buf_size, ImGuiDataType data_type, const void* p_data, const char* format)\n{\n"
    "static int SwarmlabDecimalPoint(char* buf, int length)  // Swarm Lab: '.' between digits as the language writes it\n{\n    const char point = GImGui->PlatformLocaleDecimalPoint;\n    for (int i = 1; point != '.' && i + 1 < length; i++)\n        if (buf[i] == '.' && buf[i - 1] >= '0' && buf[i - 1] <= '9' && buf[i + 1] >= '0' && buf[i + 1] <= '9')\n            buf[i] = point;\n    return length;\n}\n\nint ImGui::DataTypeFormatString(char* buf, int buf_size, ImGuiDataType data_type, const void* p_data, const char* format)\n{\n"
    1)
  _swarmlab_hook_edit(
    "        return ImFormatString(buf, buf_size, format, *(const float*)p_data);\n    if (data_type == ImGuiDataType_Double)\n        return ImFormatString(buf, buf_size, format, *(const double*)p_data);\n"
    "        return SwarmlabDecimalPoint(buf, ImFormatString(buf, buf_size, format, *(const float*)p_data));\n    if (data_type == ImGuiDataType_Double)\n        return SwarmlabDecimalPoint(buf, ImFormatString(buf, buf_size, format, *(const double*)p_data));\n"
    1)
  _swarmlab_hook_edit(
    "bool ImGui::DataTypeApplyOpFromText(const char* buf, const char* initial_value_buf, ImGuiDataType data_type, void* p_data, const char* format)\n{\n"
    "bool ImGui::DataTypeApplyOpFromText(const char* buf, const char* initial_value_buf, ImGuiDataType data_type, void* p_data, const char* format)\n{\n    char swarmlab_buf[64], swarmlab_initial[64];  // Swarm Lab: a typed ',' reads as '.'\n    ImStrncpy(swarmlab_buf, buf, IM_ARRAYSIZE(swarmlab_buf));\n    ImStrncpy(swarmlab_initial, initial_value_buf ? initial_value_buf : \"\", IM_ARRAYSIZE(swarmlab_initial));\n    for (char* c = swarmlab_buf; *c; c++) if (*c == ',') *c = '.';\n    for (char* c = swarmlab_initial; *c; c++) if (*c == ',') *c = '.';\n    buf = swarmlab_buf;\n    if (initial_value_buf) initial_value_buf = swarmlab_initial;\n"
    1)
  _swarmlab_hook_edit(
    "(c != c_decimal_point) && (c != '-')"
    "(c != c_decimal_point) && (c != '.') && (c != ',') && (c != '-')"
    2)

  file(WRITE "${out}.tmp" "${src}")
  file(COPY_FILE "${out}.tmp" "${out}" ONLY_IF_DIFFERENT)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${imgui_dir}/imgui_widgets.cpp")
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()

function(swarmlab_imgui_core_with_hooks imgui_dir out_var)
  file(READ "${imgui_dir}/imgui.cpp" src)
  set(out "${CMAKE_CURRENT_BINARY_DIR}/generated/imgui_with_hooks.cpp")
  _swarmlab_hook_edit(
    "#include \"imgui_internal.h\"\n"
    "#include \"imgui_internal.h\"\nextern bool ParallelDomHook_Unnamed(ImGuiID id);  // Swarm Lab: app/ui/parallel_dom\n"
    1)
  _swarmlab_hook_edit(
    "            if (!g.LogEnabled)\n                return true;\n    return false;\n}\n"
    "            if (!g.LogEnabled && !(g.TestEngineHookItems && ParallelDomHook_Unnamed(id)))\n                return true;\n    return false;\n}\n"
    1)
  # Where ImGui draws a label or a line of text: the parallel DOM compares the width the text
  # needs with the room it is drawn in (the clip rectangle), to tell when it is cut off
  # (ParallelDom::text_drawn). clip: an explicit clip rectangle, or null for the draw list's.
  set(text_hook "if (g.TestEngineHookItems) ParallelDomHook_TextDrawn(&g, ")
  _swarmlab_hook_edit(
    "extern bool ParallelDomHook_Unnamed(ImGuiID id);  // Swarm Lab: app/ui/parallel_dom\n"
    "extern bool ParallelDomHook_Unnamed(ImGuiID id);  // Swarm Lab: app/ui/parallel_dom\nextern void ParallelDomHook_TextDrawn(ImGuiContext* ctx, ImDrawList* draw_list, ImVec2 pos, ImVec2 size, const char* text, const char* text_end, const ImVec4* clip);\n"
    1)
  # RenderText: a label or a line, clipped by its window (or table cell)
  _swarmlab_hook_edit(
    "    if (text != text_display_end)\n    {\n        window->DrawList->AddText(g.Font, g.FontSize, pos, GetColorU32(ImGuiCol_Text), text, text_display_end);\n"
    "    if (text != text_display_end)\n    {\n        ${text_hook}window->DrawList, pos, CalcTextSize(text, text_display_end, false, 0.0f), text, text_display_end, NULL);\n        window->DrawList->AddText(g.Font, g.FontSize, pos, GetColorU32(ImGuiCol_Text), text, text_display_end);\n"
    1)
  # RenderTextWrapped: wrapped at wrap_width (a word longer than that still overflows)
  _swarmlab_hook_edit(
    "    if (text != text_end)\n    {\n        window->DrawList->AddText(g.Font, g.FontSize, pos, GetColorU32(ImGuiCol_Text), text, text_end, wrap_width);\n"
    "    if (text != text_end)\n    {\n        ${text_hook}window->DrawList, pos, CalcTextSize(text, text_end, false, wrap_width), text, text_end, NULL);\n        window->DrawList->AddText(g.Font, g.FontSize, pos, GetColorU32(ImGuiCol_Text), text, text_end, wrap_width);\n"
    1)
  # RenderTextClippedEx: a button's, a combo's or a title's label, clipped to its frame
  _swarmlab_hook_edit(
    "    // Render\n    if (need_clipping)\n    {\n        ImVec4 fine_clip_rect(clip_min->x, clip_min->y, clip_max->x, clip_max->y);\n"
    "    // Render\n    { ImGuiContext& g = *GImGui; ImVec4 room(clip_min->x, clip_min->y, clip_max->x, clip_max->y); ${text_hook}draw_list, pos, text_size, text, text_display_end, &room); }\n    if (need_clipping)\n    {\n        ImVec4 fine_clip_rect(clip_min->x, clip_min->y, clip_max->x, clip_max->y);\n"
    1)
  # RenderTextEllipsis: a tab's label, shortened with "..." when longer than its room
  _swarmlab_hook_edit(
    "    const ImVec2 text_size = text_size_if_known ? *text_size_if_known : CalcTextSize(text, text_end_full, false, 0.0f);\n\n    //draw_list->AddLine("
    "    const ImVec2 text_size = text_size_if_known ? *text_size_if_known : CalcTextSize(text, text_end_full, false, 0.0f);\n    { ImVec4 room(pos_min.x, pos_min.y, ImMin(pos_max.x, clip_max_x), pos_max.y); ${text_hook}draw_list, pos_min, text_size, text, text_end_full, &room); }\n\n    //draw_list->AddLine("
    1)
  # A window's stored name follows the label it is begun with (the same ### id, another
  # language): ImGui 1.86 renews it only while the Ctrl+Tab list shows it, but the parallel DOM
  # names its regions and swarmlab.state() its windows from it, so a window first opened in
  # Spanish kept its Spanish name in German.
  _swarmlab_hook_edit(
    "        bool window_title_visible_elsewhere = false;\n"
    "        bool window_title_visible_elsewhere = true;  // Swarm Lab: the parallel DOM shows it\n"
    1)
  file(WRITE "${out}.tmp" "${src}")
  file(COPY_FILE "${out}.tmp" "${out}" ONLY_IF_DIFFERENT)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${imgui_dir}/imgui.cpp")
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()

# swarmlab_imgui_with_hooks(<imgui_dir>): the static library swarmlab_imgui, ImGui 1.86 with
# its SDL2 and OpenGL3 backends and the hooks above, for the desktop and the page alike (each
# adds its GL flavour and SDL2).
function(swarmlab_imgui_with_hooks imgui_dir)
  swarmlab_imgui_widgets_with_hooks("${imgui_dir}" imgui_widgets)
  swarmlab_imgui_core_with_hooks("${imgui_dir}" imgui_core)
  add_library(swarmlab_imgui STATIC
    ${imgui_core} ${imgui_dir}/imgui_draw.cpp ${imgui_dir}/imgui_tables.cpp
    ${imgui_widgets} ${imgui_dir}/misc/cpp/imgui_stdlib.cpp
    ${imgui_dir}/backends/imgui_impl_sdl.cpp ${imgui_dir}/backends/imgui_impl_opengl3.cpp)
  target_include_directories(swarmlab_imgui SYSTEM PUBLIC ${imgui_dir} ${imgui_dir}/backends ${imgui_dir}/misc/cpp)
  target_compile_definitions(swarmlab_imgui PUBLIC IMGUI_ENABLE_TEST_ENGINE)
endfunction()
