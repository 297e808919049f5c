# Writes a C++ source holding every string table in assets/i18n/ (each a raw string literal),
# so the desktop and the page carry their languages inside the binary.
# Usage: cmake -DINPUT_DIR=assets/i18n -DOUTPUT=file.cpp -P embed_tables.cmake
file(GLOB tables "${INPUT_DIR}/*.json")
# English is the keys themselves: it needs no table in the binary.
list(FILTER tables EXCLUDE REGEX "/en\\.json$")
list(SORT tables)
set(entries "")
set(bodies "")
set(index 0)
foreach(table ${tables})
  get_filename_component(code "${table}" NAME_WE)
  file(READ "${table}" text)
  string(APPEND bodies "const char table_${index}[] = R\"swarmlab_i18n(${text})swarmlab_i18n\";\n")
  string(APPEND entries "    {\"${code}\", {table_${index}, sizeof table_${index} - 1}},\n")
  math(EXPR index "${index} + 1")
endforeach()
file(WRITE "${OUTPUT}.tmp"
  "// Generated from assets/i18n/*.json by embed_tables.cmake; do not edit.\n"
  "#include \"i18n/embedded_tables.h\"\n\n"
  "namespace swarmlab {\nnamespace {\n${bodies}}  // namespace\n\n"
  "std::string_view embedded_table(std::string_view code) {\n"
  "  static const struct { std::string_view code, text; } all[] = {\n${entries}    {{}, {}},  // the end (and the whole list while only English ships)\n  };\n"
  "  for (const auto& t : all)\n    if (t.code == code) return t.text;\n  return {};\n}\n\n"
  "}  // namespace swarmlab\n")
# Only a changed table touches the source, so an unchanged build compiles nothing.
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
