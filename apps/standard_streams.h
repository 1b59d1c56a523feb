#pragma once

namespace plywood::apps {

// Before anything else runs: a standard stream the caller closed (`plywood ... >&-`, `2>&-`) is
// opened on /dev/null, so that no file plywood opens later takes its number and receives what is
// printed (a sweep's progress lines went into its sweep.lock); and SIGPIPE is ignored, so a reader
// that went away (`plywood sweep ... 2>&1 | head -1`) fails a write instead of killing plywood,
// and its runs, mid-sweep.
void PrepareStandardStreams();

// After the command returned `exit_code`: flushes stdout and, when it or stderr lost its reader (a
// pipe closed early), dies of SIGPIPE as it would have at the write, now that every file is
// written; when stdout could not be written otherwise (`>/dev/full`), says so on one line and
// returns 1 if the command had succeeded. Else returns `exit_code`.
int FinishStandardStreams(int exit_code);

}  // namespace plywood::apps
