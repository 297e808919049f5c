#include <cstddef>
#include <cstdio>

#include "ui/platform/cjk_font.h"

extern const unsigned char noto_sans_sc_subset_otf[];
extern const std::size_t noto_sans_sc_subset_otf_size;

// Built in, so never fetched and never retried; fonts.cpp checks it all the same (it is cheap),
// and should it be refused the window draws Chinese in English and says so on stderr only.

namespace swarmlab {
namespace {

bool refused = false;
CjkFontNews pending_news = CjkFontNews::none;

}  // namespace

std::string_view cjk_font() {
  if (refused) return {};
  return {reinterpret_cast<const char*>(noto_sans_sc_subset_otf), noto_sans_sc_subset_otf_size};
}

void request_cjk_font() {}

CjkFontNews cjk_font_news() {
  const CjkFontNews news = pending_news;
  pending_news = CjkFontNews::none;
  return news;
}

bool cjk_font_missing() { return refused; }

void refuse_cjk_font(std::string_view why) {
  std::fprintf(stderr, "swarmlab: the built-in Chinese font was refused: %.*s\n", int(why.size()),
               why.data());
  refused = true;
  pending_news = CjkFontNews::given_up;
}

void retry_cjk_font() {}

}  // namespace swarmlab
