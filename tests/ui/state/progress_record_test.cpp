#include "ui/state/progress_record.h"

#include <doctest/doctest.h>

#include <string>

namespace swarmlab {

TEST_CASE("progress record: what a stored text is decides what is done with it") {
  CHECK(progress_record_kind("") == ProgressRecordKind::none);
  CHECK(progress_record_kind(" \n") == ProgressRecordKind::none);
  CHECK(progress_record_kind(R"({"version": 1, "welcomed": true, "lessons": {}})") ==
        ProgressRecordKind::readable);
  // Cut off, not an object, or no version this app writes: not ours to write over.
  CHECK(progress_record_kind(R"({"version": 1, "welcomed": tr)") == ProgressRecordKind::unreadable);
  CHECK(progress_record_kind("[1, 2]") == ProgressRecordKind::unreadable);
  CHECK(progress_record_kind(R"({"welcomed": true})") == ProgressRecordKind::unreadable);
  CHECK(progress_record_kind(R"({"version": "1"})") == ProgressRecordKind::unreadable);
  CHECK(progress_record_kind(R"({"version": 0})") == ProgressRecordKind::unreadable);
  CHECK(progress_record_kind(R"({"version": 1, "welcomed": true})") == ProgressRecordKind::readable);
  // A preset has a version too, but no welcome and no lessons: it is no progress.
  CHECK(progress_record_kind(R"({"version": 1, "name": "Four masses", "J": 1, "dt": 0.01})") ==
        ProgressRecordKind::unreadable);
  CHECK(progress_record_kind(R"({"version": 1, "lessons": [1]})") == ProgressRecordKind::unreadable);
  CHECK(progress_record_kind(R"({"version": 1, "welcomed": "yes"})") == ProgressRecordKind::unreadable);
  // A newer build's record: its version above the one this build writes.
  CHECK(progress_record_kind(R"({"version": 2, "lessons": []})") == ProgressRecordKind::newer);
  CHECK(progress_record_kind("{\"version\": " + std::to_string(kProgressVersion + 1) + "}") ==
        ProgressRecordKind::newer);
}

TEST_CASE("progress record: a record left alone is never written; the notice names the copy") {
  CHECK(progress_writes(ProgressTrouble::none));
  CHECK(progress_writes(ProgressTrouble::not_saved));  // tried again on every change
  CHECK(progress_writes(ProgressTrouble::unreadable_set_aside));
  CHECK_FALSE(progress_writes(ProgressTrouble::unreadable_left));
  CHECK_FALSE(progress_writes(ProgressTrouble::newer));
  CHECK(progress_trouble_text(ProgressTrouble::none, "").empty());
  const std::string aside =
      progress_trouble_text(ProgressTrouble::unreadable_set_aside, "swarmlab.progress.unreadable-x");
  CHECK(aside.find("swarmlab.progress.unreadable-x") != std::string::npos);
  CHECK(progress_trouble_text(ProgressTrouble::not_saved, "").find("cannot be saved") !=
        std::string::npos);
  CHECK(progress_trouble_text(ProgressTrouble::newer, "").find("newer version") != std::string::npos);
}

}  // namespace swarmlab
