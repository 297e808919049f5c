#pragma once
/// Strict JSON reading for the files people share (presets, lessons): one value and nothing
/// after it, and no key given twice in one object (JSON leaves that open and nlohmann would
/// silently keep the last one).

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string_view>

namespace swarm {

/// A key given twice; what() names its path, e.g. "particles[2].m: given twice (each key at
/// most once)".
struct DuplicateKey : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Parses text; throws DuplicateKey, or nlohmann's parse_error for text that is not JSON.
nlohmann::json parse_strict_json(std::string_view text);

}  // namespace swarm
