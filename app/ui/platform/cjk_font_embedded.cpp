#include <cstddef>

#include "ui/platform/cjk_font.h"

extern const unsigned char noto_sans_sc_subset_otf[];
extern const std::size_t noto_sans_sc_subset_otf_size;

namespace swarmlab {

std::string_view cjk_font() {
  return {reinterpret_cast<const char*>(noto_sans_sc_subset_otf), noto_sans_sc_subset_otf_size};
}

void request_cjk_font() {}

bool cjk_font_arrived() { return false; }

}  // namespace swarmlab
