#include "ui/state/progress_record.h"

#include <nlohmann/json.hpp>

#include "i18n/printed.h"
#include "i18n/translator.h"

namespace swarmlab {

ProgressRecordKind progress_record_kind(const std::string& text) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) return ProgressRecordKind::none;
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object()) return ProgressRecordKind::unreadable;
  // Every record this app wrote has its version; without one it is not ours to write over.
  const auto version = j.find("version");
  if (version == j.end() || !version->is_number_integer()) return ProgressRecordKind::unreadable;
  if (version->get<long long>() > kProgressVersion) return ProgressRecordKind::newer;
  if (version->get<long long>() < 1) return ProgressRecordKind::unreadable;
  // Lesson progress says whether the welcome was seen, or holds lessons: a preset, which has a
  // version too, is no progress.
  const auto welcomed = j.find("welcomed"), lessons = j.find("lessons");
  if (welcomed == j.end() && lessons == j.end()) return ProgressRecordKind::unreadable;
  if (welcomed != j.end() && !welcomed->is_boolean()) return ProgressRecordKind::unreadable;
  if (lessons != j.end() && !lessons->is_object()) return ProgressRecordKind::unreadable;
  return ProgressRecordKind::readable;
}

bool progress_writes(ProgressTrouble trouble) {
  return trouble != ProgressTrouble::unreadable_left && trouble != ProgressTrouble::newer;
}

std::string progress_trouble_text(ProgressTrouble trouble, const std::string& aside) {
  switch (trouble) {
    case ProgressTrouble::none:
      return {};
    case ProgressTrouble::not_saved:
      return tr("Your lesson progress cannot be saved here (the storage is full, blocked or "
                "private): it lasts until Swarm Lab is closed. Download it to keep it, and load "
                "it again next time.");
    case ProgressTrouble::unreadable_set_aside:
      return printed(tr("Your saved lesson progress could not be read, so lessons start afresh. "
                        "It is kept aside, not deleted, as \u201c%s\u201d."),
                     aside.c_str());
    case ProgressTrouble::unreadable_left:
      return tr("Your saved lesson progress could not be read, nor copied aside: it is left as it "
                "was, and progress made now lasts until Swarm Lab is closed. Download it to keep "
                "it.");
    case ProgressTrouble::newer:
      return tr("Your lesson progress was saved by a newer version of Swarm Lab. This version "
                "leaves it alone, so progress made now lasts until Swarm Lab is closed. Download "
                "it to keep it.");
  }
  return {};
}

}  // namespace swarmlab
