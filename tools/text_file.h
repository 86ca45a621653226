// Reading a whole input file (a scene, a model, a language source) for the tools, with the
// cases std::ifstream lets through made errors: a directory opens and reads as an empty file,
// and a read that fails part way (an I/O error) would otherwise look like a shorter file.
#pragma once

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace pf::tools {

// The contents of `path` in `text`; false, with why it cannot be read in `why` ("No such file or
// directory", "it is a directory"), otherwise.
inline bool readTextFile(const std::string& path, std::string& text, std::string& why) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    why = "it is a directory";
    return false;
  }
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    why = errno ? std::strerror(errno) : "it cannot be opened";
    return false;
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) {
    why = "an error while reading it";
    return false;
  }
  text = std::move(ss).str();
  return true;
}

}  // namespace pf::tools
