#pragma once
// SHA-256 (FIPS 180-4), self-contained: the digest that seals an ensemble's run records
// (run_record.h), where the program must run the same natively and in the browser's wasm
// without a crypto library.

#include <string>
#include <string_view>

namespace swarmlab::ensemble {

/// The SHA-256 of the bytes, as 64 lowercase hex digits.
std::string sha256_hex(std::string_view bytes);

}  // namespace swarmlab::ensemble
