#pragma once

namespace plywood::apps {

// A umask that takes the owner's own permissions away (`umask 0777`, `0200`) makes every folder and
// file plywood creates one it cannot enter, write or read back as any user but root: a run failed
// on one line ("OUT.partial-PID/config.yaml: cannot write: Permission denied") leaving OUT and its
// staging folder, mode 000, behind, and `train` its scratch folder in TMPDIR. Refused before
// anything is made; root, whom file modes do not stop, runs as before.
// @throws std::invalid_argument "umask 0777: ..." naming the fix.
void RequireAUmaskThatLeavesTheOwnerItsFiles();

}  // namespace plywood::apps
