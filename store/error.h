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

}  // namespace areagraph
