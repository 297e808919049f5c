#include "files/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

#include "files/temp_file_registry.h"

namespace swarmlab {
namespace {

/// Where an output path leads: the file to replace (a symlink's target), whether it exists,
/// and a key that is the same for two spellings of one file.
struct Resolved {
  std::string error;   // "" when the path may be written
  std::string target;  // the path actually renamed over
  bool exists = false;
  struct stat st {};
  std::string key;
};

std::string folder_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string name_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string canonical(const std::string& path) {
  char buffer[PATH_MAX];
  return ::realpath(path.c_str(), buffer) ? std::string(buffer) : std::string();
}

Resolved resolve(const std::string& path) {
  Resolved r;
  r.target = path;
  struct stat link {};
  if (::lstat(path.c_str(), &link) == 0) {
    if (S_ISLNK(link.st_mode)) {
      r.target = canonical(path);
      if (r.target.empty() || ::stat(r.target.c_str(), &r.st) != 0) {
        r.error = path +
                  ": is a symlink to nothing (swarmlab writes through a symlink only to "
                  "an existing file)";
        return r;
      }
    } else {
      r.st = link;
    }
    r.exists = true;
    if (S_ISDIR(r.st.st_mode)) {
      r.error = path + ": is a directory, not a file";
      return r;
    }
    if (!S_ISREG(r.st.st_mode)) {
      r.error = path + ": is a device, FIFO or socket; swarmlab replaces only regular files";
      return r;
    }
    if (::access(r.target.c_str(), W_OK) != 0) {
      r.error = path + ": no permission to write the file";
      return r;
    }
  } else if (errno != ENOENT) {
    r.error = path + ": cannot write here (" + std::strerror(errno) + ")";
    return r;
  }
  // The temporary is created, and the rename done, in the target's folder.
  const std::string folder = folder_of(r.target);
  struct stat dir {};
  if (::stat(folder.c_str(), &dir) != 0 || !S_ISDIR(dir.st_mode)) {
    r.error = path + ": cannot write here (the folder " + folder + " does not exist)";
    return r;
  }
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    r.error = path + ": cannot write here (no permission to create files in " + folder + ")";
    return r;
  }
  r.key = canonical(folder) + "/" + name_of(r.target);
  return r;
}

/// A new file beside target, opened with O_CREAT|O_EXCL: it cannot be a user's file, and it is
/// registered for removal on SIGINT/SIGTERM before it exists. Returns the descriptor (or -1)
/// and sets name.
int create_unique(const std::string& target, std::string& name) {
  static std::atomic<unsigned> counter{0};
  // One generator per thread: an ensemble's runs write their records at once.
  thread_local std::mt19937_64 random{std::random_device{}()};
  // A long file name leaves room for the suffix within NAME_MAX (255).
  const std::string base = name_of(target).substr(0, 120);
  for (int attempt = 0; attempt < 16; ++attempt) {
    char suffix[80];
    std::snprintf(suffix, sizeof suffix, ".swarmlab-%ld-%u-%08llx.tmp", long(::getpid()), counter++,
                  static_cast<unsigned long long>(random() & 0xffffffffu));
    name = folder_of(target) + "/." + base + suffix;
    if (!register_temp_file(name)) return -1;
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    const int error = errno;
    unregister_temp_file(name);
    if (error != EEXIST) return errno = error, -1;
  }
  return errno = EEXIST, -1;
}

std::string write_all(int fd, const std::string& contents) {
  const char* p = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return std::strerror(n < 0 ? errno : EIO);
    p += n, left -= std::size_t(n);
  }
  return {};
}

void remove_temp(const std::string& name) {
  ::unlink(name.c_str());
  unregister_temp_file(name);
}

}  // namespace

std::string check_output_path(const std::string& path) { return resolve(path).error; }

std::string check_output_paths(const std::vector<std::string>& paths) {
  std::vector<std::pair<std::string, Resolved>> seen;
  for (const std::string& path : paths) {
    if (path.empty()) continue;
    Resolved r = resolve(path);
    if (!r.error.empty()) return r.error;
    for (const auto& [other, o] : seen) {
      const bool same_inode =
          r.exists && o.exists && r.st.st_dev == o.st.st_dev && r.st.st_ino == o.st.st_ino;
      if (same_inode || r.key == o.key)
        return path + ": is given twice as an output (also as " + other + ")";
    }
    seen.emplace_back(path, std::move(r));
  }
  return {};
}

OutputFiles::~OutputFiles() { discard(); }

void OutputFiles::discard() {
  for (const Staged& s : staged_) remove_temp(s.temp);
  staged_.clear();
}

std::string OutputFiles::stage(const std::string& path, const std::string& contents) {
  return stage_file(path, &contents, nullptr);
}

std::string OutputFiles::stage(const std::string& path,
                               const std::function<std::string(const std::string&)>& fill) {
  return stage_file(path, nullptr, &fill);
}

std::string OutputFiles::temp_of(const std::string& path) const {
  for (const Staged& s : staged_)
    if (s.path == path) return s.temp;
  return {};
}

std::string OutputFiles::stage_file(const std::string& path, const std::string* contents,
                                    const std::function<std::string(const std::string&)>* fill) {
  const Resolved r = resolve(path);
  if (!r.error.empty()) return r.error;
  for (const Staged& s : staged_)
    if (resolve(s.path).key == r.key)
      return path + ": is given twice as an output (also as " + s.path + ")";
  std::string temp;
  const int fd = create_unique(r.target, temp);
  if (fd < 0) return path + ": cannot create a temporary file (" + std::strerror(errno) + ")";
  std::string error;
  // The new file keeps the old one's permissions.
  if (r.exists) ::fchmod(fd, r.st.st_mode & 07777);
  if (contents) error = write_all(fd, *contents);
  if (error.empty() && contents && ::fsync(fd) != 0 && errno != EINVAL)
    error = std::strerror(errno);
  if (::close(fd) != 0 && error.empty()) error = std::strerror(errno);
  if (!error.empty()) {
    remove_temp(temp);
    return path + ": write failed (" + error + ")";
  }
  if (fill) {
    if (std::string e = (*fill)(temp); !e.empty()) {
      remove_temp(temp);
      return e;
    }
  }
  staged_.push_back({path, r.target, temp});
  return {};
}

std::string OutputFiles::commit() {
  // Looked at again: a run can be long, and a file can have become a FIFO meanwhile.
  for (const Staged& s : staged_)
    if (std::string e = check_output_path(s.path); !e.empty()) {
      discard();
      return e;
    }
  // A hard link to each old file, so that a failed rename can put the old files back. Where
  // the file system has no hard links, that one file cannot be restored.
  std::vector<std::string> backups(staged_.size());
  std::vector<bool> existed(staged_.size());
  for (std::size_t i = 0; i < staged_.size(); ++i) {
    existed[i] = ::access(staged_[i].target.c_str(), F_OK) == 0;
    if (!existed[i]) continue;
    std::string name;
    const int fd = create_unique(staged_[i].target, name);
    if (fd < 0) continue;
    ::close(fd);
    ::unlink(name.c_str());
    if (::link(staged_[i].target.c_str(), name.c_str()) == 0)
      backups[i] = name;
    else
      unregister_temp_file(name);
  }
  std::string error;
  std::size_t done = 0;
  for (; done < staged_.size(); ++done)
    if (::rename(staged_[done].temp.c_str(), staged_[done].target.c_str()) != 0) {
      error = staged_[done].path + ": cannot move into place (" + std::strerror(errno) +
              "); the old files are left as they were";
      break;
    }
  if (!error.empty())
    for (std::size_t j = done; j-- > 0;) {
      if (!backups[j].empty())
        ::rename(backups[j].c_str(), staged_[j].target.c_str());
      else if (!existed[j])
        ::unlink(staged_[j].target.c_str());
    }
  for (std::size_t i = 0; i < staged_.size(); ++i) {
    if (i >= done) ::unlink(staged_[i].temp.c_str());
    unregister_temp_file(staged_[i].temp);
    if (!backups[i].empty()) remove_temp(backups[i]);
  }
  staged_.clear();
  return error;
}

std::string write_file_atomically(const std::string& path, const std::string& contents) {
  OutputFiles files;
  if (std::string e = files.stage(path, contents); !e.empty()) return e;
  return files.commit();
}

}  // namespace swarmlab
