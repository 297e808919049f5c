#pragma once
// SHA-256 (FIPS 180-4), self-contained: the digest that seals an ensemble's run records
// (ensemble/run_record.h) and the check of the fonts the page fetches (cjk_font_web.cpp), where
// the program must run the same natively and in the browser's wasm, on plain http too, without
// a crypto library.

#include <string>
#include <string_view>

namespace swarmlab {

/// The SHA-256 of the bytes, as 64 lowercase hex digits.
std::string sha256_hex(std::string_view bytes);

}  // namespace swarmlab
