#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# The Green's-function operator build of BP5-QD on N ranks: wall time and
# the machine's peak memory of one or more rsfcycle binaries, run in turn
# (A B A B ...), each on the shipped prm/seas-bp5-qd.prm with
# `Local refinements` REFINEMENTS (2: 1 km fault cells, as shipped; 3:
# 500 m) and an end time of 1 s, so that the run is the operator's build,
# its file and a few steps.
#
# Memory is the machine's, not a process's: MemTotal - MemAvailable of
# /proc/meminfo, sampled every 0.2 s, minus its value before the run. A
# factor in a shared-memory window is then counted once; a per-process
# peak (the RSS of /usr/bin/time) counts its pages in every rank that
# reads them. So run it on an otherwise quiet machine.
#
# usage: bench_shared_factor.sh [-n PAIRS] [-r RANKS] [-l REFINEMENTS] BINARY...
# prints one line per run: the binary, the wall time [s], the peak memory
# above idle [GiB], the operator's build time from the run's log [s]
# (the run folders are made under ${TMPDIR:-/tmp} and removed).
set -euo pipefail
source "$(dirname "$0")/../common.sh"
help_if_asked "${1:-}"

pairs=1 ranks=2 refinements=2
while getopts n:r:l: option; do
    case $option in
    n) pairs=$OPTARG ;;
    r) ranks=$OPTARG ;;
    l) refinements=$OPTARG ;;
    *) die "usage: bench_shared_factor.sh [-n PAIRS] [-r RANKS] [-l REFINEMENTS] BINARY..." ;;
    esac
done
shift $((OPTIND - 1))
(($# > 0)) || die "give at least one rsfcycle binary"
for binary in "$@"; do [[ -x $binary ]] || die "$binary: not an executable"; done

prm_dir=$(cd "$(dirname "$0")/../../prm" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/bench-shared-factor.XXXXXX")
trap 'rm -rf "$work"' EXIT
cat >"$work/bp5.prm" <<EOF
include $prm_dir/seas-bp5-qd.prm
set End time         = 1
set Output directory = $work/run
subsection Mesh file
  set File = $prm_dir/meshes/seas-bp5.msh
end
subsection Mesh
  set Local refinements = $refinements
end
EOF
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

used_kib() {
    awk '/^MemTotal:/ { t = $2 } /^MemAvailable:/ { a = $2 } END { print t - a }' /proc/meminfo
}

for ((p = 0; p < pairs; ++p)); do
    for binary in "$@"; do
        rm -rf "$work/run"
        idle=$(used_kib)
        start=$(date +%s.%N)
        mpirun -np "$ranks" --oversubscribe "$binary" --force "$work/bp5.prm" \
            >"$work/stdout" 2>&1 &
        pid=$!
        peak=0
        while kill -0 "$pid" 2>/dev/null; do
            now=$(used_kib)
            ((now > peak)) && peak=$now
            sleep 0.2
        done
        status=0
        wait "$pid" || status=$?
        end=$(date +%s.%N)
        build=$(sed -n "s/^| *Green's function operator *| *[0-9]* *| *\([0-9.e+]*\)s.*/\1/p" \
            "$work/run/log.txt" 2>/dev/null | head -1)
        printf '%s\twall %.1f s\tpeak %.2f GiB\toperator %s s\texit %d\n' \
            "$binary" "$(echo "$end - $start" | bc)" \
            "$(echo "($peak - $idle) / 1048576" | bc -l)" "${build:-?}" "$status"
        ((status == 0)) || tail -3 "$work/stdout" >&2
    done
done
