#pragma once

namespace plywood::eval {

// Prints scans per second (one core) of every line extractor on a fixed 361-beam LMS 200 scan of
// an L-shaped room with 1 cm range noise (plywood bench's line-extraction part).
void PrintLineExtractorBench(double seconds_per_extractor = 0.3);

}  // namespace plywood::eval
