#!/usr/bin/env bash
# Builds the Debian package from the build tree BUILD (cpack -G DEB), unpacks it with dpkg -x into
# a scratch root and uses it from there as the package lays it out under /usr: the CLI on a
# shipped mission, an installed figure command on its output, the man pages, the bash
# completion, the docs, and the Python module with that root's python path.
#   check_deb.sh BUILD_DIR WORK_DIR VERSION
set -euo pipefail
build=$1 work=$2 version=$3
rm -rf "$work"
mkdir -p "$work/empty"
root=$work/root
fail() { echo "check_deb: $*" >&2; exit 1; }

echo "== cpack -G DEB"
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/cpack" >/dev/null
deb=$work/cpack/ceilplan_${version}_$(dpkg --print-architecture).deb
test -f "$deb" || fail "no $deb: $(ls "$work/cpack")"
depends=$(dpkg-deb --field "$deb" Depends)
echo "Depends: $depends"
for package in python3 python3-numpy python3-matplotlib libc6 libstdc++6 liboctomap libompl; do
  [[ $depends == *"$package"* ]] || fail "Depends lacks $package"
done
dpkg -x "$deb" "$root"

echo "== the CLI, from an empty directory"
cd "$work/empty"
ceilplan=$root/usr/bin/ceilplan
first=$("$ceilplan" --version)
first=${first%%$'\n'*}
[[ $first == "ceilplan $version "* ]] || fail "--version: $first"
"$ceilplan" tour --mission "$root/usr/share/ceilplan/maps/bridge.yaml" --mode ceiling --out "$work/tour" >"$work/tour.txt"
test -f "$work/tour/mission.plan"
# The tour's last line names the installed figure command, and tour --help the installed page.
figures=$(tail -1 "$work/tour.txt")
[[ $figures == "figures: $root/usr/bin/ceilplan-plot-tour $work/tour" ]] || fail "tour says: $figures"
page=$root/usr/share/doc/ceilplan/docs/missions.md
help=$("$ceilplan" tour --help)
[[ $help == *"mission file ($page)"* ]] || fail "tour --help does not name $page"
test -f "$page"

echo "== the installed figure command, as the tour names it"
MPLCONFIGDIR=$work/matplotlib ${figures#figures: }
test -s "$work/tour/tour_views.png" && test -s "$work/tour/tour_soc.svg"

echo "== man pages, bash completion, docs"
for page in ceilplan ceilplan-tour ceilplan-duty ceilplan-plan; do
  [[ $(zcat "$root/usr/share/man/man1/$page.1.gz") == *$'\n'".TH ${page^^} "* ]] || fail "man page $page"
done
completion=$root/usr/share/bash-completion/completions/ceilplan
# shellcheck source=/dev/null
source "$completion"
COMP_WORDS=(ceilplan tour --mo)
COMP_CWORD=2
_ceilplan
[[ ${COMPREPLY[*]} == "--mode" ]] || fail "completion of 'ceilplan tour --mo': ${COMPREPLY[*]}"
for file in README.md CHANGELOG.md LICENSE docs/tours.md docs/figures/duty_fec_month.png; do
  test -f "$root/usr/share/doc/ceilplan/$file" || fail "no /usr/share/doc/ceilplan/$file"
done

echo "== the Python module with the root's python path"
export PYTHONPATH=$root/usr/lib/python3/dist-packages
/usr/bin/python3 - "$root" "$version" "$root/usr/share/ceilplan/maps/bridge.yaml" "$work/tour/tour.json" <<'PY'
import json, sys
import ceilplan
root, version, mission, tour_json = sys.argv[1:]
assert ceilplan.__file__.startswith(root), ceilplan.__file__
assert ceilplan.__version__ == version, ceilplan.__version__
tour = ceilplan.plan_tour(ceilplan.Mission.load(mission), mode="ceiling")
cli = json.load(open(tour_json))["charge_ah"]
assert abs(tour.charge_ah - cli) <= 1e-9, (tour.charge_ah, cli)
print("installed module", ceilplan.__file__, ceilplan.__version__, "plan_tour charge_ah", tour.charge_ah)
PY
# Under an interpreter that cannot import numpy, the import itself fails and names it.
message=$(/usr/bin/python3 -c 'import sys; sys.modules["numpy"] = None; import ceilplan' 2>&1 | tail -1) && true
[[ $message == "ImportError: ceilplan needs numpy"* ]] || fail "import without numpy: $message"
echo "deb OK: $deb"
