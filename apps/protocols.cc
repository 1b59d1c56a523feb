#include "apps/protocols.h"

namespace plywood::apps {

// Each protocol lives in its own apps/<name>_protocol.cc; register it here.
const std::map<std::string, Protocol>& Protocols() {
  static const std::map<std::string, Protocol> protocols{};
  return protocols;
}

}  // namespace plywood::apps
