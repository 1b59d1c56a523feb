#pragma once

#include <functional>
#include <memory>
#include <string>

#include "robot/control/controller.h"
#include "robot/drive/diff_drive_spec.h"
#include "robot/plugins/parameter_map.h"
#include "robot/plugins/registry.h"

namespace plywood::robot {

// A controller user code adds by name (docs/plugins.md). The factory gets the robot's nominal
// drive and the controller's options (the keys beside `type`, except rate_hz and steer_by, which
// the host reads), and throws std::invalid_argument "<key>: <what is wrong>" for a bad option.
struct RegisteredController {
  std::string name;
  std::function<std::unique_ptr<Controller>(const DiffDriveSpec& nominal,
                                            const ParameterMap& options)>
      make;
};

using ControllerRegistry = Registry<RegisteredController>;

}  // namespace plywood::robot
