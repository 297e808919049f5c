#pragma once
// The language to start in, and the choice kept between visits: a file in the user's config
// folder and the locale's environment on the desktop (language_memory_files.cpp), localStorage
// and the page's choice in the browser (language_memory_web.cpp).

#include <string>

namespace swarmlab {

/// The language to start in: on the desktop the one chosen last (View > Language), else the
/// system locale's (LC_ALL, LC_MESSAGES, LANG); in the browser the one the page chose before
/// the app started (the address's #lang=, else the one chosen last, else the browser's
/// languages: web/page_text.js). A code of app/i18n/language.h; English's when nothing fits.
std::string startup_language();

/// Keeps `code` for the next visit; a failure (read-only home, storage refused) only means the
/// next visit starts in the system's language.
void remember_language(const std::string& code);

}  // namespace swarmlab
