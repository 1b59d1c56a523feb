#include "apps/protocols.h"

#include "apps/umbmark_protocol.h"

namespace plywood::apps {

// Each protocol lives in its own apps/<name>_protocol.cc; register it here.
const std::map<std::string, Protocol>& Protocols() {
  static const std::map<std::string, Protocol> protocols{
      {"umbmark", UmbmarkProtocol},
  };
  return protocols;
}

}  // namespace plywood::apps
