#!/usr/bin/env bash
# usage: energy_watch.sh MPM
# The energy balance watch on colliding_disks_fast.prm (no loads):
# 1. warn (default): status 0, one warning naming step 4000 (t = 0.8);
# 2. stop: status 2, the same message as the error;
# 3. the same disks neo-Hookean: no warning (a hyperelastic model keeps
#    the energy to 0.1%);
# 4. a ramped body force: "energy balance not watched", naming the body;
# 5. a 3D beam at nu = 0.49 with the mass-metric filter: the warning names
#    the filter of Bodies/Body 0 as a cause; the compliance metric: none.
set -u
mpm=$1
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "FAIL: $*"; exit 1; }
case=$here/colliding_disks_fast.prm
rm -rf warn stop neo ramp mass compliance && mkdir warn stop neo ramp mass compliance

(cd warn && "$mpm" "$case" > out.txt 2> err.txt) || { cat warn/err.txt; fail "warn: non-zero status"; }
[ "$(grep -c 'mpm: warning:' warn/err.txt)" = 1 ] || { cat warn/err.txt; fail "warn: expected one warning"; }
grep -q "mpm: warning: at step 4000 (t = 0.8): kinetic + strain energy less the work of the loads has grown by .* of the largest energy" warn/err.txt \
  || { cat warn/err.txt; fail "warn: the warning does not name step 4000"; }
echo "OK   warn: $(cut -c1-150 warn/err.txt)"

printf 'include %s\nsubsection Output\n  set Energy balance check = stop\nend\n' "$case" > stop/case.prm
(cd stop && "$mpm" case.prm > out.txt 2> err.txt); rc=$?
[ "$rc" = 2 ] || { cat stop/err.txt; fail "stop: status $rc, expected 2"; }
grep -q "mpm: the simulation stopped at step 4000 (t = 0.8): kinetic + strain energy" stop/err.txt \
  || { cat stop/err.txt; fail "stop: the message does not name step 4000"; }
echo "OK   stop: status 2"

sed 's/Model = linear elastic/Model = neo-Hookean/; s/subsection Linear elastic/subsection Neo-Hookean/' "$case" > neo/case.prm
(cd neo && "$mpm" case.prm > out.txt 2> err.txt) || { cat neo/err.txt; fail "neo-Hookean: non-zero status"; }
grep -q "energy balance watched (tolerance 0.1)" neo/out.txt || fail "neo-Hookean: not watched"
! grep -q "warning" neo/err.txt || { cat neo/err.txt; fail "neo-Hookean: unexpected warning"; }
echo "OK   neo-Hookean: no warning"

printf 'include %s\nsubsection Bodies\n  subsection Body 1\n    set Body force = 0; -t\n  end\nend\n' "$case" > ramp/case.prm
(cd ramp && "$mpm" case.prm > out.txt 2> err.txt) || { cat ramp/err.txt; fail "ramp: non-zero status"; }
grep -q "energy balance not watched: Bodies/Body 1/Body force varies" ramp/out.txt \
  || { cat ramp/out.txt; fail "ramp: the header does not say why the balance is not watched"; }
echo "OK   ramped load: not watched, the body named"

beam=$here/cantilever_3d_mass_filter.prm
(cd mass && "$mpm" "$beam" > out.txt 2> err.txt) || { cat mass/err.txt; fail "mass filter: non-zero status"; }
grep -q "mpm: warning: at step .*or by the assumed-stress filter of Bodies/Body 0 with Filter metric = mass" mass/err.txt \
  || { cat mass/err.txt; fail "mass filter: the warning does not name the filter"; }
echo "OK   mass-metric filter named: $(grep -o 'or by the assumed-stress filter of [^,]*' mass/err.txt)"

sed 's/Filter metric = mass/Filter metric = compliance/' "$beam" > compliance/case.prm
(cd compliance && "$mpm" case.prm > out.txt 2> err.txt) || { cat compliance/err.txt; fail "compliance filter: non-zero status"; }
! grep -q "warning" compliance/err.txt || { cat compliance/err.txt; fail "compliance filter: unexpected warning"; }
echo "OK   compliance-metric filter: no warning"
