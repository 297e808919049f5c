#pragma once
// Output files that cannot hurt. Each is written to a temporary beside its target (a name
// made with O_CREAT|O_EXCL from the pid, a counter and a random number, so no user's file is
// ever opened), then renamed over it, so an interrupted run never leaves half a file.
// The rules:
//   - only a regular file is replaced, or a new one created; a directory, a device, a FIFO or
//     a socket is refused, and so is a file the user may not write;
//   - a symlink is written through: its target file is replaced and the link stays a link (a
//     link to nothing is refused);
//   - several outputs commit together (OutputFiles): all are written to temporaries first,
//     then all renamed; if anything fails the old files are back as they were;
//   - SIGINT and SIGTERM remove the temporaries (temp_file_registry.h).

#include <functional>
#include <string>
#include <vector>

namespace swarmlab {

/// Checks, before a run, that path can be written by these rules: "" when it can, else a
/// message "PATH: why not". Looks only; creates nothing.
std::string check_output_path(const std::string& path);

/// check_output_path for each non-empty path, and no file given twice (through a symlink, a
/// hard link or "./" included).
std::string check_output_paths(const std::vector<std::string>& paths);

/// Outputs that are written together: stage each, then commit. Destroying an OutputFiles that
/// was not committed removes its temporaries and leaves every target untouched.
class OutputFiles {
 public:
  OutputFiles() = default;
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;
  ~OutputFiles();

  /// Writes contents to a temporary for path. "" or a message; on a message nothing changed.
  std::string stage(const std::string& path, const std::string& contents);

  /// Creates an empty temporary for path and lets fill write it by name (a child process that
  /// renders a PNG, say); fill returns "" or a message.
  std::string stage(const std::string& path,
                    const std::function<std::string(const std::string& temp)>& fill);

  /// The temporary staged for path, or "" (to read back what was staged, e.g. an SVG).
  std::string temp_of(const std::string& path) const;

  /// Renames every temporary over its target. On failure restores the targets already
  /// replaced and returns a message; on success the temporaries are gone.
  std::string commit();

 private:
  struct Staged {
    std::string path;    // as the user gave it
    std::string target;  // the file actually replaced (a symlink's target)
    std::string temp;
  };
  std::string stage_file(const std::string& path, const std::string* contents,
                         const std::function<std::string(const std::string&)>* fill);
  void discard();
  std::vector<Staged> staged_;
};

/// One output on its own: stage + commit.
std::string write_file_atomically(const std::string& path, const std::string& contents);

}  // namespace swarmlab
