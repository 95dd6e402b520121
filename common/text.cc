#include "common/text.h"

#include <sstream>

namespace areagraph {

std::string FormatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string ShortKey(const std::string& cache_key) { return cache_key.substr(0, 12); }

}  // namespace areagraph
