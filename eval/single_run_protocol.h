#pragma once

#include "eval/protocol.h"

namespace plywood::eval {

// `protocol: single` (the default): one run of the experiment, then every post-run scorer that
// applies (seed 001's map when the sonar explorer drove, the `lines:` section's extractors), the
// run directory of docs/run_outputs.md, the snapshot and a printed summary.
int SingleRunProtocol(const ProtocolContext& context);

}  // namespace plywood::eval
