#include "render/mesa_driver.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace plywood::render {

void RequireTheReproducibleMesaDriver() {
  const char* driver = std::getenv("GALLIUM_DRIVER");
  if (driver == nullptr || std::string(driver).empty() || std::string(driver) == "llvmpipe") return;
  throw std::invalid_argument(
      std::string("GALLIUM_DRIVER: ") + driver +
      ": plywood draws its pictures with Mesa's llvmpipe, so that the same seed gives the same "
      "bytes (softpipe draws other pixels; other names crash Mesa): unset GALLIUM_DRIVER or set "
      "it to llvmpipe");
}

}  // namespace plywood::render
