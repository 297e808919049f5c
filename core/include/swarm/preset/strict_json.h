#pragma once
/// Strict JSON reading for the files people share (presets, lessons): one value and nothing
/// after it, and no key given twice in one object (JSON leaves that open and nlohmann would
/// silently keep the last one).

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>

namespace swarm {

/// A key given twice; what() names its path, e.g. "particles[2].m: given twice (each key at
/// most once)".
struct DuplicateKey : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Parses text; throws DuplicateKey, or nlohmann's parse_error for text that is not JSON.
nlohmann::json parse_strict_json(std::string_view text);

/// A parse error of `text` as a person reads it, in one line: where (line and column, counted
/// from 1 as an editor does) and what is wrong, without nlohmann's "[json.exception...]" prefix,
/// e.g. "line 3, column 12: unexpected end of input; expected '[', '{', or a literal".
std::string json_syntax_error(const nlohmann::json::parse_error& e, std::string_view text);

/// Any other error of nlohmann's (a number beyond a double's range) without its code:
/// "number overflow parsing '1e999'", made printable.
std::string json_error_text(const nlohmann::json::exception& e);

}  // namespace swarm
