#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Time two rsfcycle binaries on the same stretch of a run, side by side:
# both resume a copy of RUN (a run folder whose checkpoint lies where the
# cost is wanted, e.g. inside an event) and step for SPAN seconds of
# simulated time.
#   benchmarks/seas-bp3/bench_resume.sh RUN SPAN NEW_BINARY OLD_BINARY
# Prints farm-bench's table (A: NEW, B: OLD) and whether the two copies end
# with the same last row of time-series.csv.
set -euo pipefail
run=$(realpath "$1"); span=$2; new=$(realpath "$3"); old=$(realpath "$4")
work=$(mktemp -d)
cp -r "$run" "$work/base"
# the checkpoint's time: a resume with an End time before it cuts the
# files to the checkpoint and steps no further
cp -r "$work/base" "$work/probe"
sed -i "s/^set End time .*/set End time = 1/" "$work/probe/parameters.prm"
"$new" --resume "$work/probe" > /dev/null 2>&1 || true
t0=$(tail -n 1 "$work/probe/time-series.csv" | cut -d, -f1)
# (a run ends within 1e-10 t of End time: SPAN must exceed that)
end=$(/usr/bin/python3 -c "print(repr($t0 + $span))")
sed -i "s/^set End time .*/set End time = $end/" "$work/base/parameters.prm"
cat > "$work/one.sh" <<EOS
#!/bin/bash
rm -rf "$work/\$2" && cp -r "$work/base" "$work/\$2" && "\$1" --resume "$work/\$2" > /dev/null 2>&1
EOS
chmod +x "$work/one.sh"
farm-bench -n 3 --warmup 0 --timeout 1800 --vs "$work/one.sh $old old" -- "$work/one.sh" "$new" new
if cmp -s <(tail -n 1 "$work/new/time-series.csv") <(tail -n 1 "$work/old/time-series.csv"); then
  echo "the same last row of time-series.csv"
else
  echo "the last rows of time-series.csv differ"
fi
rm -rf "$work"
