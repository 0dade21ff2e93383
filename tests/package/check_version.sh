#!/usr/bin/env bash
# The version is set once, in project(VERSION) of the top-level CMakeLists.txt (passed here as
# VERSION), and every place a user reads it agrees: the CLI, the Python module, the CMake package,
# the Debian package and the newest release in CHANGELOG.md.
#   check_version.sh BUILD_DIR SOURCE_DIR VERSION CEILPLAN PYTHON
set -euo pipefail
build=$1 source=$2 version=$3 ceilplan=$4 python=$5
fail() { echo "check_version: $*" >&2; exit 1; }
expect() {  # expect WHERE ACTUAL
  [[ $2 == "$version" ]] || fail "$1 says '$2', project(VERSION) is $version"
  echo "$1: $2"
}
first=$("$ceilplan" --version)
first=${first%%$'\n'*}
expect "ceilplan --version" "$(sed -E 's/^ceilplan ([^ ]+) \(git .*/\1/' <<<"$first")"
second=$("$ceilplan" version)
second=${second%%$'\n'*}
expect "ceilplan version" "$(cut -d' ' -f2 <<<"$second")"
expect "python ceilplan.__version__" "$(PYTHONPATH=$build/python "$python" -c 'import ceilplan; print(ceilplan.__version__)')"
expect "ceilplanConfigVersion.cmake" "$(sed -nE 's/^set\(PACKAGE_VERSION "([^"]+)"\)/\1/p' "$build/ceilplanConfigVersion.cmake")"
expect "CPackConfig.cmake" "$(sed -nE 's/^set\(CPACK_PACKAGE_VERSION "([^"]+)"\)/\1/p' "$build/CPackConfig.cmake")"
expect "CHANGELOG.md's newest release" "$(grep -m1 -oE '^## \[[0-9][^]]*\]' "$source/CHANGELOG.md" | tr -d '#[] ')"
