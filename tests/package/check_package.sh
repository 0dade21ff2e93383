#!/usr/bin/env bash
# Installs the build tree BUILD into a temporary prefix and uses the package from outside the
# source tree: examples/ built against find_package(ceilplan), the installed `ceilplan` run from
# an empty directory (no --vehicle), and the installed Python module.
#   check_package.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work/empty"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
share=$prefix/share/ceilplan/maps
test -f "$prefix/lib/cmake/ceilplan/ceilplanConfig.cmake"
test -f "$prefix/include/ceilplan/ceilplan.hpp"
test -f "$share/bridge.yaml"

echo "== examples against the installed package"
cmake -S "$source/examples" -B "$work/examples" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/examples" -j2 >/dev/null
for example in "$source"/examples/*.cpp; do
  name=$(basename "$example" .cpp)
  test -x "$work/examples/$name" || { echo "examples/$name.cpp was not built against the package"; exit 1; }
done
cd "$work/empty"
"$work/examples/plan_route" "$share/bridge.bt" -4 0 0.5 10 0 5.5
"$work/examples/tour_both_modes" "$share/bridge.yaml" "$work/example_out" | tail -3
test -f "$work/example_out/ceiling.plan" && test -f "$work/example_out/free.plan"

echo "== the installed command line, from an empty directory"
ceilplan=$prefix/bin/ceilplan
"$ceilplan" --version
"$ceilplan" probe --map "$share/bridge.bt" --at 10,0,5.5 >/dev/null
"$ceilplan" plan --map "$share/bridge.bt" --start=-4,0,0.5 --goal=10,0,5.5 --time-limit-s 2 --out "$work/plan" >/dev/null
"$ceilplan" evaluate --map "$share/bridge.bt" --path "$work/plan/path.csv" | grep -q "valid: true"
"$ceilplan" tour --mission "$share/bridge.yaml" --mode ceiling --out "$work/tour" >/dev/null
test -f "$work/tour/mission.plan"

echo "== the installed Python module"
python=${CEILPLAN_PYTHON:-python3}
# A sanitizer build's module needs the ASan and C++ runtimes loaded before python3 (which leaks
# at exit).
preload=()
if [[ -n ${CEILPLAN_SANITIZER_PRELOAD:-} ]]; then
  preload=(env "LD_PRELOAD=$CEILPLAN_SANITIZER_PRELOAD" ASAN_OPTIONS=detect_leaks=0)
fi
PYTHONPATH=$prefix/lib/python3/dist-packages "${preload[@]}" "$python" - "$share/bridge.yaml" "$work/tour/tour.json" <<'PY'
import json, sys
import ceilplan
tour = ceilplan.plan_tour(ceilplan.Mission.load(sys.argv[1]), mode="ceiling")
cli = json.load(open(sys.argv[2]))["charge_ah"]
assert abs(tour.charge_ah - cli) <= 1e-9, (tour.charge_ah, cli)
print("python plan_tour charge_ah", tour.charge_ah, "== ceilplan tour", cli)
PY
echo "package OK"
