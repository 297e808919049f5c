#pragma once
// The student's stored lesson progress as a record: the version this build writes, what a text
// found in the store is (and so what is done with it), and the one notice that says when
// progress is not kept as usual. A record is never destroyed without a word: one that cannot be
// read is kept aside under another name, one from a newer version is left alone.

#include <string>

namespace swarmlab {

/// The record's "version" this build writes; a record with a higher one is a newer build's.
constexpr int kProgressVersion = 1;

/// What a text found in the progress store is.
enum class ProgressRecordKind {
  none,        ///< nothing stored yet
  readable,    ///< this version's or an older one's, with "welcomed" or "lessons": read, then saved over
  unreadable,  ///< not a record (cut off, edited by hand, another program's): kept aside
  newer,       ///< a newer build's record: left alone, never written over
};

/// Sorts a stored text; whitespace alone counts as none.
ProgressRecordKind progress_record_kind(const std::string& text);

/// Why progress is not kept as usual (none: nothing to say).
enum class ProgressTrouble {
  none,
  not_saved,             ///< the store refused to write (full, blocked, a private window)
  unreadable_set_aside,  ///< the record could not be read; it is kept under another name
  unreadable_left,       ///< the record could not be read nor copied: left as it was
  newer,                 ///< a newer build's record: left as it was
};

/// Whether progress made now is written to the store (not while a record is left alone).
bool progress_writes(ProgressTrouble trouble);

/// The notice in the language in use; aside: the name the unreadable record is kept under.
std::string progress_trouble_text(ProgressTrouble trouble, const std::string& aside);

}  // namespace swarmlab
