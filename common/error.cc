#include "common/error.h"

#include "common/text.h"

namespace areagraph {

MapStepError::MapStepError(const std::string& map_name, const std::string& step,
                           const std::string& cause)
    : Error("map '" + map_name + "', " + step + ": " + OneLine(cause)),
      map_name_(map_name),
      step_(step),
      cause_(OneLine(cause)) {}

}  // namespace areagraph
