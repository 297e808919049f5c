#include "files/text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace swarmlab {
namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a file";
}

std::string size_text(std::size_t bytes) {
  return bytes % (std::size_t(1) << 20) == 0 ? std::to_string(bytes >> 20) + " MB"
                                              : std::to_string(bytes) + " bytes";
}

/// "" when st is a regular file of at most `limit` bytes, else why not.
std::string refusal(const struct stat& st, std::size_t limit) {
  if (!S_ISREG(st.st_mode))
    return "not a regular file (" + kind_of(st.st_mode) + "); only regular files are read";
  if (st.st_size < 0 || std::size_t(st.st_size) > limit)
    return "larger than " + size_text(limit) + ", the most this file may hold";
  return {};
}

}  // namespace

TextFile read_regular_file(const std::string& path, std::size_t limit) {
  TextFile out;
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    out.missing = errno == ENOENT || errno == ENOTDIR;
    out.error = "cannot open the file (" + std::string(std::strerror(errno)) + ")";
    return out;
  }
  if (out.error = refusal(st, limit); !out.error.empty()) return out;
  // O_NONBLOCK: a FIFO swapped in after the stat opens at once instead of waiting for a
  // writer, and fstat below refuses it; on a regular file it changes nothing.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    out.error = "cannot open the file (" + std::string(std::strerror(errno)) + ")";
    return out;
  }
  if (::fstat(fd, &st) != 0) {
    out.error = "cannot read the file (" + std::string(std::strerror(errno)) + ")";
  } else if (out.error = refusal(st, limit); out.error.empty()) {
    // One byte more than the limit is asked for, so a file that grows while it is read is
    // caught rather than cut.
    out.text.resize(std::size_t(st.st_size) + 1);
    std::size_t have = 0;
    for (;;) {
      if (have == out.text.size()) {
        if (have > limit) break;
        out.text.resize(std::min(limit + 1, 2 * have + 4096));
      }
      const ssize_t n = ::read(fd, &out.text[have], out.text.size() - have);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        out.error = "cannot read the file (" + std::string(std::strerror(errno)) + ")";
        break;
      }
      if (n == 0) break;
      have += std::size_t(n);
    }
    if (out.error.empty() && have > limit)
      out.error = "larger than " + size_text(limit) + ", the most this file may hold";
    out.text.resize(out.error.empty() ? have : 0);
  }
  ::close(fd);
  return out;
}

std::string read_text_file(const std::string& path, std::string& error, std::size_t limit) {
  TextFile file = read_regular_file(path, limit);
  if (!file.error.empty()) {
    error = path + ": " + file.error;
    return {};
  }
  return std::move(file.text);
}

}  // namespace swarmlab
