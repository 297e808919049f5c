#include "atomic_file.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>

namespace swarmlab {

std::string write_file_atomically(const std::string& path, const std::string& contents) {
  const std::string temp = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) return path + ": cannot create the file";
    out << contents;
    out.flush();
    if (!out) {
      std::remove(temp.c_str());
      return path + ": write failed (disk full?)";
    }
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    std::remove(temp.c_str());
    return path + ": cannot replace the file";
  }
  return {};
}

}  // namespace swarmlab
