#!/usr/bin/env bash
# usage: full_disk.sh MPM CASE.prm NP
#
# A checkpoint or an output file that does not fit on the disk ends the
# run with status 2 and a message naming the directory and its free
# space; the latest checkpoint stays intact, and once there is room
# `mpm --resume` ends as the uninterrupted run.
# 1. ref/: the case (without vtu files) run to its end.
# 2. The same in a file system (tmpfs) with room for two checkpoints
#    and the small files: the third is refused before it is begun (status 2,
#    "no room on the disk", the free space named, the latest intact).
# 3. The file system enlarged: `mpm --resume` continues from the latest
#    checkpoint and ends with ref's statistics, byte for byte.
# 4. With vtu output into a file system of 40 kB: status 2, the output
#    directory and its free space named.
# 5. File systems with few file entries, so that the disk fills during a
#    checkpoint (p4est's write included): status 2 every time.
# Needs tmpfs mounts (root): skipped with status 77 where not permitted.
set -u
mpm=$1 case=$2 np=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
run_mpm() {
  if [ "$np" -gt 1 ]; then timeout 300 mpirun -np "$np" "$mpm" "$@"
  else timeout 300 "$mpm" "$@"; fi
}
fail() { echo "FAIL: $*"; exit 1; }
here=$(pwd)
# The screen goes outside the small file system: written into it, it
# could be cut off by the very shortage the run reports.
screen=$here/screen.txt
# Runs case.prm in $disk; fails (showing the screen) unless mpm stopped
# with status 2. $1 names the case in the failure.
expect_status_2() {
  (cd "$disk" && run_mpm case.prm > "$screen" 2>&1)
  local rc=$?
  [ "$rc" = 2 ] || { cat "$screen"; fail "$1: exit status $rc, expected 2"; }
}
disk=$here/disk
# a mount left by an interrupted run (possibly stacked) is taken down
# A run that just ended may still hold the mount for a moment (OpenMPI's
# helper of a run without mpirun has its directory there): umount is
# retried, and detached at last, so that no mount is left stacked.
release_disk() {
  local attempt
  for attempt in 1 2 3 4 5 6 7 8 9 10; do
    umount "$disk" 2>/dev/null && return 0
    sleep 0.5
  done
  umount -l "$disk"
}
unmount_all() { while mountpoint -q "$disk" 2>/dev/null; do release_disk || break; done; }
cleanup() { cd "$here"; unmount_all; true; }
trap cleanup EXIT
trap 'exit 1' INT TERM

unmount_all
rm -rf ref "$disk" && mkdir ref "$disk" || exit 1
if ! mount -t tmpfs -o size=1m tmpfs "$disk" 2>/dev/null; then
  echo "SKIPPED: cannot mount a tmpfs here (needs root and permission)"
  exit 77
fi
release_disk

cat > ref/case.prm <<P
include $case
subsection Output
  set Write vtu = false
  set Write csv = false
end
P
(cd ref && run_mpm case.prm > screen.txt 2>&1) \
  || { cat ref/screen.txt; fail "the reference run failed"; }
latest=$(cat ref/results/checkpoint/latest.txt)
checkpoint_kb=$(du -sk "ref/results/checkpoint/$latest" | cut -f1)

# room for two checkpoints and the small files, not for a third
size_kb=$((checkpoint_kb * 2 + 32))
mount -t tmpfs -o size=${size_kb}k tmpfs "$disk" || fail "mount"
cp ref/case.prm "$disk/"
expect_status_2 "full disk"
grep -q "while writing the checkpoint of step [0-9]*: no room on the disk: about .* MB are needed in 'results', the file system has .* MB free" "$screen" \
  || { cat "$screen"; fail "full disk: the message names neither the checkpoint nor the free space"; }
grep -q "is intact" "$screen" \
  || { cat "$screen"; fail "full disk: the message does not name the intact checkpoint"; }
echo "OK   checkpoint on a full disk: status 2, $(grep -o 'the checkpoint of step.*free' "$screen")"

mount -o remount,size=$((size_kb * 4))k "$disk" || fail "remount"
(cd "$disk" && run_mpm --resume case.prm > screen2.txt 2>&1) \
  || { cat "$disk/screen2.txt"; fail "the resume after freeing space failed"; }
cmp -s ref/results/statistics.txt "$disk/results/statistics.txt" \
  || fail "the resumed run's statistics differ from the uninterrupted run's"
echo "OK   resumed once there was room: statistics equal the uninterrupted run's"
release_disk

mount -t tmpfs -o size=40k tmpfs "$disk" || fail "mount"
cat > "$disk/case.prm" <<P
include $case
subsection Output
  set Write vtu = true
end
subsection Checkpointing
  set Steps between checkpoints = 0
end
P
expect_status_2 "vtu on a full disk"
grep -q "cannot write .* in 'results' (the file system of 'results' has" "$screen" \
  || { cat "$screen"; fail "vtu on a full disk: the message does not name the directory and its free space"; }
echo "OK   output on a full disk: status 2, $(grep -o "cannot write [^:]*" "$screen" | head -1)"

# 5. A disk that fills during the checkpoint, after the check: a file
#    system with room for bytes but few file entries, swept over the
#    number of entries so that each file of the output and the checkpoint
#    is the first to fail in one of the runs, p4est's own file among them
#    in 2D. Every run ends with status 2 and names the folder (never a
#    core dump from p4est's abort).
seen_p4est=0
sweep() {
  local entries
  for entries in "$@"; do
    mount -t tmpfs -o size=20m,nr_inodes=$entries tmpfs "$disk" || fail "mount"
    cp ref/case.prm "$disk/"
    expect_status_2 "$entries file entries"
    grep -q "mpm: the simulation stopped while \(opening the output\|writing the checkpoint of step [0-9]*\): .*\(results\|No space\)" "$screen" \
      || { cat "$screen"; fail "$entries file entries: the message names no folder"; }
    grep -q "p4est stopped on a failed write" "$screen" && seen_p4est=1
    release_disk
  done
}
sweep 5 6 7 8 9 10 11 12 13 14 15 16
if grep -q "dimension 1" ref/screen.txt; then
  echo "OK   file entries run out (5 to 16): status 2 each time"
else
  # On several ranks the order in which the ranks create their files
  # varies from run to run, so the entry count at which p4est's write is
  # the first to fail can move by one: the middle of the sweep is run
  # again (each run must still end with status 2) until it is hit.
  for attempt in 1 2 3 4 5; do
    [ "$seen_p4est" = 1 ] && break
    sweep 9 10 11 12 13
  done
  [ "$seen_p4est" = 1 ] || fail "no run of the sweep failed inside p4est's write: widen the sweep"
  echo "OK   file entries run out (5 to 16): status 2 each time, once inside p4est's write"
fi
