#pragma once
/// The string tables of assets/i18n/, built into the program (embed_tables.cmake).

#include <string_view>

namespace swarmlab {

/// The JSON text of the table for a language code ("es", "pt-BR"), or empty when none ships.
std::string_view embedded_table(std::string_view code);

}  // namespace swarmlab
