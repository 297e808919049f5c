# Writes a C++ source holding assets/i18n/languages.json and every string table in assets/i18n/
# (each a raw string literal), so the desktop and the page carry their languages inside the
# binary. Usage: cmake -DINPUT_DIR=assets/i18n -DOUTPUT=file.cpp -P embed_tables.cmake
file(READ "${INPUT_DIR}/languages.json" languages)
# The first language's texts are the keys themselves: it needs no table in the binary. The rest
# of the table is checked where it is read (app/i18n/language_table.cpp, scripts/i18n.py).
string(JSON source ERROR_VARIABLE problem GET "${languages}" 0 code)
if(problem)
  message(FATAL_ERROR "assets/i18n/languages.json: [0].code: the first language's code is needed "
                      "(the language of the texts, which has no table in the binary): ${problem}")
endif()
file(GLOB tables "${INPUT_DIR}/*.json")
list(REMOVE_ITEM tables "${INPUT_DIR}/languages.json" "${INPUT_DIR}/${source}.json")
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
  "namespace swarmlab {\nnamespace {\n"
  "const char language_table[] = R\"swarmlab_i18n(${languages})swarmlab_i18n\";\n${bodies}}  // namespace\n\n"
  "std::string_view embedded_language_table() { return {language_table, sizeof language_table - 1}; }\n\n"
  "std::string_view embedded_table(std::string_view code) {\n"
  "  static const struct { std::string_view code, text; } all[] = {\n${entries}    {{}, {}},  // the end (and the whole list while only English ships)\n  };\n"
  "  for (const auto& t : all)\n    if (t.code == code) return t.text;\n  return {};\n}\n\n"
  "}  // namespace swarmlab\n")
# Only a changed table touches the source, so an unchanged build compiles nothing.
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
