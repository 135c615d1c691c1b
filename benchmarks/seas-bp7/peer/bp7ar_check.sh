#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Is hbi-bp7.patch inert without its keyword? Runs HBI's own example examples/bp7ar.in (BP7 without the
# prescribed nucleation) with the BP5 build (hbi-bp5.patch only) and with the BP7 build (+ hbi-bp7.patch),
# and compares every native output file byte for byte.
#
# usage: BP5_SRC=DIR BP7_SRC=DIR benchmarks/seas-bp7/peer/bp7ar_check.sh OUTDIR
#   BP5_SRC  HBI checkout with hbi-bp5.patch, built by ../../seas-bp5/peer/run.sh (required; only read)
#   BP7_SRC  HBI checkout with hbi-bp5.patch + hbi-bp7.patch, built by run.sh (required; only read)
#   TMAX     optional: replace bp7ar.in's tmax (HBI yr of 365 d; the example has 10.0)
#   NICE     nice level (default 10)
#   COMPARE_ONLY=1  only compare the outputs already in OUTDIR (BP5_SRC, BP7_SRC not needed)
# The shipped examples/bp7ar_param.dat has 10 columns and no header line, while bp7ar.in asks for 2
# columns (a, tau) with a header, as examples/bp7ar_param.py writes them; at the pinned commit the example
# stops with "End of file". We write the 2-column file from the shipped columns 2 (a) and 6 (tau), which
# are the values bp7ar_param.py computes (checked: a = 0.004 exactly where r < 0.2 km at the cell centres).
set -euo pipefail
NICE=${NICE:-10}
OUT=${1:?usage: BP5_SRC=DIR BP7_SRC=DIR $0 OUTDIR}
if [ "${COMPARE_ONLY:-0}" != 1 ]; then
[ -n "${BP5_SRC:-}" ] && [ -n "${BP7_SRC:-}" ] || { echo "$(basename "$0"): set BP5_SRC and BP7_SRC to the built HBI checkouts of the BP5 and BP7 peer runs" >&2; exit 2; }
for b in bp5bin bp7bin; do
  d=$OUT/$b; rm -rf "$d"; mkdir -p "$d/examples" "$d/output"
  sed 's#examples/bp7ar_param.dat#examples/bp7ar_param2.dat#' "$BP5_SRC/examples/bp7ar.in" > "$d/examples/bp7ar.in"
  [ -n "${TMAX:-}" ] && sed -i "s/^tmax .*/tmax $TMAX/" "$d/examples/bp7ar.in"
  { printf 'a\ttau\n'; awk '{print $2 "\t" $6}' "$BP5_SRC/examples/bp7ar_param.dat"; } > "$d/examples/bp7ar_param2.dat"
done
( cd "$OUT/bp5bin" && OMP_NUM_THREADS=1 /usr/bin/time -v -o time.txt nice -n "$NICE" "$BP5_SRC/lhbiem" examples/bp7ar.in > log.txt 2>&1 )
( cd "$OUT/bp7bin" && OMP_NUM_THREADS=1 /usr/bin/time -v -o time.txt nice -n "$NICE" "$BP7_SRC/lhbiem" examples/bp7ar.in > log.txt 2>&1 )
fi
status=0
for f in "$OUT"/bp7bin/output/*; do
  g=$OUT/bp5bin/output/$(basename "$f")
  case $(basename "$f") in
    monitor*)   # column 11 is the wall time. In line 1, nrjct (column 10) is printed before it is set, and
                # a large value runs into column 9 (i6): there, compare columns 1-8 and the last only
      if diff -q <(awk '{if (NR == 1) print $1,$2,$3,$4,$5,$6,$7,$8,$NF; else {$11=""; print}}' "$f") \
                 <(awk '{if (NR == 1) print $1,$2,$3,$4,$5,$6,$7,$8,$NF; else {$11=""; print}}' "$g") >/dev/null
      then echo "same (but wall time)  $(basename "$f")"; else echo "DIFFERENT  $(basename "$f")"; status=1; fi ;;
    *) if cmp -s "$f" "$g"; then echo "same  $(basename "$f")"; else echo "DIFFERENT  $(basename "$f")"; status=1; fi ;;
  esac
done
echo "events (n, step, onset s, HBI Mw, hypocentre cell):"; cat "$OUT/bp7bin/output/event701.dat"
grep -E "Elapsed|User time" "$OUT"/bp*bin/time.txt
exit $status
