#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# The configure step refuses what rsfcycle cannot build with, in one line
# naming it (doc/install.md): a deal.II configured without p4est, without
# Trilinos, without SUNDIALS (each a stub deal.IIConfig.cmake that has the
# others), and a missing hmat-oss (a stub deal.II with every feature and
# find_package(HMAT) disabled). Each configure must fail, print the line,
# and the line must name the feature; nothing is built.
# Usage: cmake_requirements.sh SOURCE_DIR WORK_DIR
set -u
src=$1; work=$2
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAILED: $*"; exit 1; }

# stub_dealii DIR OFF_FEATURE: a deal.II 9.4.1 "installation" whose
# configuration has every feature rsfcycle needs but OFF_FEATURE.
stub_dealii() {
  local feature
  mkdir -p "$1"
  cat > "$1/deal.IIConfigVersion.cmake" <<'CMAKE'
set(PACKAGE_VERSION 9.4.1)
set(PACKAGE_VERSION_COMPATIBLE TRUE)
CMAKE
  {
    echo 'set(DEAL_II_PACKAGE_VERSION 9.4.1)'
    echo 'set(DEAL_II_PATH ${CMAKE_CURRENT_LIST_DIR})'
    for feature in MPI P4EST TRILINOS SUNDIALS MUPARSER LAPACK; do
      if [[ $feature == "$2" ]]; then
        echo "set(DEAL_II_WITH_$feature OFF)"
      else
        echo "set(DEAL_II_WITH_$feature ON)"
      fi
    done
    echo 'macro(deal_ii_initialize_cached_variables)'
    echo 'endmacro()'
  } > "$1/deal.IIConfig.cmake"
}

# expect NAME LINE [cmake arguments]: configure must fail printing LINE.
expect() {
  local name=$1 line=$2
  shift 2
  local out
  out=$(cmake -S "$src" -B "$work/$name/build" "$@" 2>&1) &&
    fail "$name: the configure step succeeded"
  echo "$out" | grep -qF -- "$line" ||
    fail "$name: no line '$line' in: $out"
  echo "$name: refused: $line"
}

for feature in P4EST TRILINOS SUNDIALS; do
  stub_dealii "$work/no-$feature/dealii" "$feature"
  expect "no-$feature" \
    "rsfcycle needs deal.II configured with DEAL_II_WITH_$feature=ON" \
    -Ddeal.II_DIR="$work/no-$feature/dealii"
done

stub_dealii "$work/no-hmat/dealii" NONE
expect no-hmat "rsfcycle needs hmat-oss (HMATConfig.cmake): not found" \
  -Ddeal.II_DIR="$work/no-hmat/dealii" -DCMAKE_DISABLE_FIND_PACKAGE_HMAT=ON

expect no-dealii "rsfcycle needs deal.II >= 9.4: none found" \
  -Ddeal.II_DIR="$work/nowhere" -DCMAKE_FIND_ROOT_PATH="$work/nowhere" \
  -DCMAKE_FIND_ROOT_PATH_MODE_PACKAGE=ONLY
echo "OK"
