#!/usr/bin/env bash
# usage: damaged.sh MPM CASE.prm NP FILE...
#
# A checkpoint with one file damaged is refused before anything is loaded,
# and `Damaged checkpoint = use previous` resumes from the previous one.
# 1. ref/: the case run to its end on NP ranks (it keeps its two latest
#    checkpoints, each with a manifest).
# 2. For each FILE of the latest checkpoint, and each kind of damage
#    (truncated to half, one byte changed, deleted), a copy of ref/ with
#    that damage: `mpm --resume` must exit with status 1, name the file,
#    and leave the output directory as it was.
# 3. The manifest deleted, and latest.txt naming a folder that does not
#    exist: refused the same way.
# 4. One damaged file with `Damaged checkpoint = use previous`: the run
#    resumes from the previous checkpoint, says so, and ends with the
#    statistics of ref/ byte for byte.
set -u
mpm=$1 case=$2 np=$3; shift 3
files=("$@")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
run_mpm() {
  if [ "$np" -gt 1 ]; then timeout 300 mpirun -np "$np" "$mpm" "$@"
  else timeout 300 "$mpm" "$@"; fi
}
fail() { echo "FAIL: $*"; exit 1; }
snapshot() { (cd "$1/results" && find . -type f -print0 | sort -z | xargs -0 md5sum) | md5sum; }

rm -rf ref work && mkdir ref || exit 1
(cd ref && run_mpm "$case" > screen.txt 2>&1) \
  || { cat ref/screen.txt; fail "the reference run failed"; }
latest=$(cat ref/results/checkpoint/latest.txt)
n_dirs=$(find ref/results/checkpoint -mindepth 1 -maxdepth 1 -type d | wc -l)
[ "$n_dirs" = 2 ] || fail "expected the two latest checkpoints, found $n_dirs folders"
[ -f "ref/results/checkpoint/$latest/manifest.txt" ] || fail "no manifest in $latest"

# refused: status 1, the culprit named, nothing changed
refused() { # LABEL EXPECT
  local before; before=$(snapshot work)
  (cd work && run_mpm --resume "$case" > screen.txt 2>&1)
  local rc=$?
  [ "$rc" = 1 ] || { cat work/screen.txt; fail "$1: exit status $rc, expected 1"; }
  grep -qF -- "$2" work/screen.txt \
    || { cat work/screen.txt; fail "$1: the message does not contain: $2"; }
  [ "$(snapshot work)" = "$before" ] || fail "$1: the output directory was changed"
  echo "OK   $1: refused"
}
damage() { # FILE KIND
  local f=work/results/checkpoint/$latest/$1
  [ -f "$f" ] || fail "the checkpoint has no file $1"
  case $2 in
    truncated) truncate -s $(($(stat -c %s "$f") / 2)) "$f" ;;
    byte) local at=$(($(stat -c %s "$f") / 3)) old
          old=$(dd if="$f" bs=1 skip=$at count=1 2>/dev/null | od -An -tu1 | tr -d ' ')
          printf "\\$(printf '%03o' $(((old + 1) % 256)))" \
            | dd of="$f" bs=1 seek=$at conv=notrunc 2>/dev/null ;;
    deleted) rm "$f" ;;
  esac
}
for file in "${files[@]}"; do
  for kind in truncated byte deleted; do
    rm -rf work && cp -r ref work && damage "$file" "$kind"
    refused "$file $kind" "results/checkpoint/$latest/$file'"
  done
done
rm -rf work && cp -r ref work && rm "work/results/checkpoint/$latest/manifest.txt"
refused "manifest deleted" "has no readable manifest.txt"
rm -rf work && cp -r ref work && echo "step-99999999" > work/results/checkpoint/latest.txt
refused "latest.txt damaged" "step-99999999' (named by latest.txt) does not exist"

rm -rf work && cp -r ref work && damage "${files[0]}" byte
sed 's/^ *set Steps between checkpoints.*/&\n  set Damaged checkpoint = use previous/' "$case" \
  | sed "s#^include \(\.\./\)#include $(dirname "$case")/\1#" > work/previous.prm
(cd work && run_mpm --resume previous.prm > screen.txt 2>&1) \
  || { cat work/screen.txt; fail "the fallback run failed"; }
grep -q "resuming from the previous one" work/screen.txt \
  || { cat work/screen.txt; fail "the fallback run did not say it used the previous checkpoint"; }
cmp ref/results/statistics.txt work/results/statistics.txt \
  || fail "the fallback run's statistics differ from the uninterrupted run's"
echo "OK   fallback to the previous checkpoint: statistics equal"
