#include "files/text_file.h"

#include <fstream>
#include <sstream>

namespace swarmlab {

std::string read_text_file(const std::string& path, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = path + ": cannot open the file";
    return {};
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    error = path + ": cannot read the file";
    return {};
  }
  return text.str();
}

}  // namespace swarmlab
