#pragma once

#include "perception/plugins/plugin.h"

namespace lab {

// Adds this lab's algorithms to `registry`: the line extractor "lab_endpoint_fit" (options
// max_gap_m, split_distance_m, min_points, min_length_m) and the odometry estimator
// "lab_complementary" (option gyro_weight; needs the gyro). plugin.cc calls it from the plug-in's
// entry point; a program that links these sources can call it directly.
void RegisterLabAlgorithms(plywood::perception::AlgorithmRegistry& registry);

}  // namespace lab
