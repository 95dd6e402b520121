#pragma once

#include <stdexcept>
#include <string>

namespace areagraph {

// Base of all errors meant for the user: what() is one line that says what
// went wrong and, where it helps, what to do.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A bad file, image, YAML or map content.
class InputError : public Error {
 public:
  using Error::Error;
};

// A bad option key, value or combination.
class OptionsError : public Error {
 public:
  using Error::Error;
};

// The store cannot be opened, read or written.
class StoreError : public Error {
 public:
  using Error::Error;
};

// Any failure while one step (a stage, or "publish") ran for one map: the
// algorithm code throws without knowing the map, and the code that runs the
// step adds where it happened. what() reads "map 'M', stage S: <cause>".
class MapStepError : public Error {
 public:
  MapStepError(const std::string& map_name, const std::string& step, const std::string& cause);

  const std::string& map_name() const { return map_name_; }
  const std::string& step() const { return step_; }
  // The cause's own message, without the context.
  const std::string& cause() const { return cause_; }

 private:
  std::string map_name_;
  std::string step_;
  std::string cause_;
};

}  // namespace areagraph
