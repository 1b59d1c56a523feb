#pragma once
// Test fixture: hardware-side code must not include this.
#include <mujoco/mujoco.h>
