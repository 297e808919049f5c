#pragma once
/// A link that opens a lesson for a student: the page's address, then "#lesson=" and either a
/// shipped lesson's id ("#lesson=one-period") or, for any other lesson, its JSON text in
/// base64url (RFC 4648 section 5, no padding). The lesson panel's Share button and
/// swarmlab.lessonLink() write these; the page reads them back with read_lesson_link, which
/// accepts exactly these two forms (docs/lessons.md, "Sharing it").

#include <string>
#include <string_view>
#include <vector>

namespace swarmlab {

/// "#lesson=" + shipped_id when it is not empty, else "#lesson=" + base64url(json).
std::string lesson_link_fragment(const std::string& shipped_id, const std::string& json);

/// What the text after "#lesson=" asks to open: a shipped lesson's id, or lesson JSON text (to
/// be checked by parse_lesson), or one sentence saying why it is neither.
struct LessonLinkTarget {
  std::string id;
  std::string json;
  std::string error;
};
LessonLinkTarget read_lesson_link(std::string_view value, const std::vector<std::string>& shipped_ids);

/// base64url without padding (also used for the tests' links).
std::string to_base64url(std::string_view bytes);
/// The bytes of base64url text ('+', '/', '=' padding and white space of plain base64 are
/// accepted too); false when it is not base64url.
bool from_base64url(std::string_view text, std::string* bytes);

}  // namespace swarmlab
