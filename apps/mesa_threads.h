#pragma once

namespace plywood::apps {

// Mesa's llvmpipe starts a rasteriser thread per core when it draws the first picture and, when
// one cannot start, waits for it forever: under `ulimit -u 4` a run hung in its snapshot, its main
// thread waiting to join it. Under a small process limit (below kFewProcesses, a user other than
// root, LP_NUM_THREADS unset) plywood sets LP_NUM_THREADS=0, so llvmpipe draws in the snapshot
// thread itself: the same pixels (the shipped experiments' bytes do not change with it), no thread
// to wait for. Called first thing in main(), before any thread starts.
inline constexpr unsigned long kFewProcesses = 256;

void KeepMesaFromWaitingOnThreadsItCannotStart();

}  // namespace plywood::apps
