#pragma once
// vri::Error: the one exception type for bad input. Its message is a single
// line meant for the user ("cannot read 'x.raw': file is 12 bytes, expected 64").
#include <stdexcept>
#include <string>

namespace vri {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// A file that cannot be opened, read or written (the operating system said
// no: missing, a directory, no permission, short). Python raises it as OSError.
class FileError : public Error {
 public:
  using Error::Error;
};

}  // namespace vri
