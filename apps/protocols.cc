#include "apps/protocols.h"

#include "apps/seed000_protocol.h"
#include "apps/seed004_ransac_protocol.h"
#include "apps/umbmark_protocol.h"
#include "apps/weighted_gain_protocol.h"

namespace plywood::apps {

// Each protocol lives in its own apps/<name>_protocol.cc; register it here.
const std::map<std::string, Protocol>& Protocols() {
  static const std::map<std::string, Protocol> protocols{
      {"seed000_rooms", Seed000Protocol},
      {"seed004_ransac", Seed004RansacProtocol},
      {"umbmark", UmbmarkProtocol},
      {"weighted_gain_search", WeightedGainProtocol},
  };
  return protocols;
}

}  // namespace plywood::apps
