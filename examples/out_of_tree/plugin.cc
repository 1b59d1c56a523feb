// The plug-in's entry point: what `plugins: [libplywood_example.so]` in an experiment runs.

#include "perception/plugins/plugin.h"

#include "register_lab_algorithms.h"

PLYWOOD_PLUGIN(registry) { lab::RegisterLabAlgorithms(registry); }
