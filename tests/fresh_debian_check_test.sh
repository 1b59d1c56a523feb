#!/usr/bin/env bash
# scripts/fresh_debian_check stops what still runs inside its Debian root before it unmounts and
# removes it (s66 review): a daemon the README's commands start detached inside the root (munged,
# slurmctld, slurmd of tests/sweep_slurm_test.sh, should that test be killed) outlived the check,
# its root deleted under it, holding the Slurm test's ports on the host.
# The check runs from a small copy of the tree whose scripts/demo starts such a daemon (a detached
# sleep) and fails; a stand-in debootstrap (first on PATH) makes a root of bash, env, setsid and
# sleep, so nothing is fetched. Needs root (chroot, mounts); skips (77) otherwise.
#   tests/fresh_debian_check_test.sh SOURCE_ROOT
set -euo pipefail
source_root=$1
if [ "$(id -u)" -ne 0 ]; then
  echo "SKIPPED: the check needs root (chroot and mounts)"
  exit 77
fi
for tool in git chroot setsid ldd; do
  command -v "$tool" >/dev/null || { echo "SKIPPED: $tool not installed"; exit 77; }
done

work=$(mktemp -d /tmp/plywood-fresh-check-test.XXXXXX)
mark="r67-$$-$RANDOM"
stop() {
  # Whatever the check left behind: the daemon this test started, found by its own mark.
  local pids
  pids=$(pgrep -f -- "^(daemon|sleeper)-$mark" || true)
  [ -z "$pids" ] || kill -KILL $pids 2>/dev/null || true
  # And the mounts of a check that failed (killed) before its own clean-up: each made a slave
  # first (a check killed between its --rbind and its --make-rslave leaves a shared bind, whose
  # unmounts would reach the host's /sys or /dev: review68), then unmounted deepest first.
  local m mounts
  mounts=$(awk -v w="$work/" 'index($2, w) == 1 {print $2}' /proc/mounts | sort)
  for m in $mounts; do mount --make-rslave "$m" 2>/dev/null || true; done
  for m in $(echo "$mounts" | sort -r); do
    umount "$m" 2>/dev/null || umount -l "$m" 2>/dev/null || true
  done
  rm -rf --one-file-system "$work"
}
trap stop EXIT

# The tree: the check itself and a demo that starts a daemon in the root and fails.
mkdir -p "$work/tree/scripts" "$work/bin"
cp "$source_root/scripts/fresh_debian_check" "$work/tree/scripts/"
cat >"$work/tree/scripts/demo" <<EOF
#!/bin/bash
setsid bash -c "exec -a daemon-$mark sleep 3600" </dev/null >/dev/null 2>&1 &
echo "demo: a daemon started"
exit 1
EOF
chmod +x "$work/tree/scripts/demo"
git -C "$work/tree" init -q
git -C "$work/tree" add -A
git -C "$work/tree" -c user.name=t -c user.email=t@t commit -qm tree

# debootstrap's stand-in: a root of the few programs the demo above runs, and their libraries.
cat >"$work/bin/debootstrap" <<'EOF'
#!/bin/bash
set -e
root=$3
mkdir -p "$root"/{etc/apt,root,proc,sys,dev,tmp,usr/bin,bin}
for program in bash env setsid sleep; do
  path=$(command -v "$program")
  cp "$path" "$root/usr/bin/"
  for lib in $(ldd "$path" | grep -o '/[^ ]*'); do
    mkdir -p "$root$(dirname "$lib")"
    cp -n "$lib" "$root$lib"
  done
done
ln -s /usr/bin/bash "$root/bin/bash"
EOF
chmod +x "$work/bin/debootstrap"

set +e
PATH="$work/bin:$PATH" "$work/tree/scripts/fresh_debian_check" --dir "$work/root" --demo-only \
  >"$work/check.log" 2>&1
rc=$?
set -e
cat "$work/check.log"
if [ "$rc" -ne 1 ] || ! grep -q "demo: a daemon started" "$work/check.log"; then
  echo "FAIL: the check did not run the demo in its root (exit $rc)"
  exit 1
fi
if pgrep -f -- "^daemon-$mark" >/dev/null; then
  echo "FAIL: a process started in the root still runs after the check: $(pgrep -a -f -- "daemon-$mark")"
  exit 1
fi
if [ -e "$work/root" ] || grep -q "$work/root" /proc/mounts; then
  echo "FAIL: the root or a mount of it is left"
  exit 1
fi

# A TERM to the check while the demo runs (here: for an hour) ends the check at once, the demo and
# its root with it; it waited for the demo's end (s67).
mkdir -p "$work/slow/scripts"
cp "$source_root/scripts/fresh_debian_check" "$work/slow/scripts/"
printf '#!/bin/bash\necho "demo: sleeping"\nexec -a sleeper-%s sleep 3600\n' "$mark" \
  >"$work/slow/scripts/demo"
chmod +x "$work/slow/scripts/demo"
git -C "$work/slow" init -q
git -C "$work/slow" add -A
git -C "$work/slow" -c user.name=t -c user.email=t@t commit -qm slow
PATH="$work/bin:$PATH" "$work/slow/scripts/fresh_debian_check" --dir "$work/root2" --demo-only \
  >"$work/check2.log" 2>&1 &
check=$!
for _ in $(seq 300); do
  grep -qs "demo: sleeping" "$work/root2.demo.log" && break
  sleep 0.1
done
if ! grep -qs "demo: sleeping" "$work/root2.demo.log"; then
  kill -KILL "$check" 2>/dev/null || true
  cat "$work/check2.log"
  echo "FAIL: the slow demo did not start in its root"
  exit 1
fi
kill -TERM "$check"
for _ in $(seq 300); do
  kill -0 "$check" 2>/dev/null || break
  sleep 0.1
done
if kill -0 "$check" 2>/dev/null; then
  kill -KILL "$check" 2>/dev/null || true
  echo "FAIL: the check did not stop on TERM while its demo ran (30 s)"
  exit 1
fi
set +e
wait "$check"
rc=$?
set -e
cat "$work/check2.log"
if [ "$rc" -ne 130 ]; then
  echo "FAIL: the check stopped by TERM exited $rc, not 130"
  exit 1
fi
if pgrep -f -- "^sleeper-$mark" >/dev/null; then
  echo "FAIL: the demo still runs after the check stopped"
  exit 1
fi
if [ -e "$work/root2" ] || grep -q "$work/root2" /proc/mounts; then
  echo "FAIL: the stopped check left its root or a mount of it"
  exit 1
fi
echo "2 passed, 0 failed"
