#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Run-folder integrity test. On a short coarse wedge run:
#  - a checkpoint cut to 1000 bytes, one with 64 bytes overwritten in the
#    middle, one from another mesh (one refinement less) and one whose
#    format version is patched to 2 are each refused by --resume with exit
#    status 1 and one line "rsfcycle: error: DIR/checkpoint.bin: ..." that
#    says what is wrong and that checkpoint.bin.prev is intact; every file
#    of the folder is unchanged (sha256sum of each, and the list of files
#    and folders, before and after);
#  - following that advice (moving checkpoint.bin.prev to checkpoint.bin)
#    resumes the run to the same records as the uninterrupted run.
# Failed writes, with a file size limit (ulimit -f; SIGXFSZ is ignored by
# rsfcycle, so that the write fails with EFBIG):
#  - a spring-slider run stopped by the limit on time-series.csv ends with
#    one line naming the file and "File too large"; resumed without the
#    limit, it gives the uninterrupted run's events.csv and time-series.csv;
#  - a VTU snapshot over the limit: one line naming the VTU file;
#  - a checkpoint over the limit (the finished wedge run resumed, whose
#    final checkpoint is then rewritten): one line naming checkpoint.tmp,
#    checkpoint.bin and .prev unchanged and no temporary file left; resumed
#    without the limit, the run ends as before.
# A full disk, where a tmpfs can be mounted (else skipped with a message):
# the spring-slider in 128 KiB ends with one line naming the file and "No
# space left on device"; with the space freed, --resume gives the
# uninterrupted run's events.csv and time-series.csv.
# Usage: run_folder_integrity.sh RSFCYCLE SOURCE_DIR WORK_DIR
set -u
exe=$1; src=$2; work=$3
umount "$work/disk" 2> /dev/null # left mounted by a killed earlier run
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
n_pass=0; n_fail=0
pass() { n_pass=$((n_pass + 1)); }
fail() { n_fail=$((n_fail + 1)); echo "FAILED: $*"; }

make_wedge_prm() { # name, local refinements
  cat > "$1.prm" <<PRM
include $src/prm/wedge-2d.prm
include $src/tests/wedge-2d-pinned.prm
set End time = 150
set Output directory = $1
subsection Mesh
  set Global refinements = 2
  set Local refinements  = $2
end
subsection Output
  set Checkpoint steps = 50
end
PRM
}
make_slider_prm() { # name [, output directory]
  cat > "$1.prm" <<PRM
include $src/prm/spring-slider.prm
set End time = 500
set Output directory = ${2:-$1}
subsection Output
  set Checkpoint steps = 200
end
PRM
}
# the list of files and folders of a run folder and the checksum of each file
snapshot() {
  (cd "$1" && find . | sort && find . -type f | sort | xargs sha256sum)
}
# one line on stderr, starting with "rsfcycle: error: " and containing $2
one_line_error() { # stderr file, expected text
  [ "$(wc -l < "$1")" -eq 1 ] && grep -q "^rsfcycle: error: " "$1" &&
    grep -qF -- "$2" "$1"
}
# run with a file size limit of $1 KiB; Open MPI's PMIx (started by the
# wedge, which uses MPI) keeps its data in shared-memory files that the
# limit would break, unless told to keep them in its heap (gds = hash)
limited() {
  local limit=$1; shift
  (ulimit -f "$limit" && PMIX_MCA_gds=hash exec "$@")
}
same_records() { # folder a, folder b
  local f
  for f in time-series.csv base-profile.csv events.csv; do
    cmp -s "$1/$f" "$2/$f" || return 1
  done
}

make_wedge_prm wedge 3
"$exe" wedge.prm > wedge.log 2>&1 || fail "wedge run"
make_wedge_prm coarser 2
"$exe" coarser.prm > coarser.log 2>&1 || fail "coarser wedge run"
[ -f wedge/checkpoint.bin.prev ] || fail "the wedge run kept no checkpoint.bin.prev"

# A copy of the wedge folder damaged by $2 (run in it), then --resume:
# refused with the message $3 and the hint, the folder unchanged.
refused() { # name, damage, expected text
  local name=$1
  rm -rf "$name"; cp -a wedge "$name"
  (cd "$name" && eval "$2")
  cmp -s wedge/checkpoint.bin "$name/checkpoint.bin" &&
    fail "$name: the damage did not change checkpoint.bin"
  snapshot "$name" > "$name.before"
  "$exe" --resume "$name" > "$name.out" 2> "$name.err"
  local status=$?
  snapshot "$name" > "$name.after"
  if [ $status -eq 1 ] && one_line_error "$name.err" "$name/checkpoint.bin: $3" &&
     grep -qF "the previous checkpoint $name/checkpoint.bin.prev is intact: move it to $name/checkpoint.bin and resume" "$name.err" &&
     cmp -s "$name.before" "$name.after"; then
    pass
  else
    fail "$name (exit $status)"
    cat "$name.err"
    diff "$name.before" "$name.after"
  fi
  echo "$name: $(cat "$name.err")"
}
size=$(stat -c %s wedge/checkpoint.bin)
refused truncated 'head -c 1000 checkpoint.bin > cut && mv cut checkpoint.bin' \
  "truncated (1000 of $size bytes)"
refused damaged "head -c 64 /dev/zero | tr '\\0' 'Z' | dd of=checkpoint.bin bs=1 seek=$((size / 2)) conv=notrunc 2> /dev/null" \
  "checksum mismatch: the checkpoint is damaged"
refused other-mesh 'cp ../coarser/checkpoint.bin checkpoint.bin' \
  "written for $(grep -o '[0-9]* unknowns' coarser.log | head -1), this run has $(grep -o '[0-9]* unknowns' wedge.log | head -1 | cut -d' ' -f1)"
refused other-format "printf '\\x05' | dd of=checkpoint.bin bs=1 seek=8 conv=notrunc 2> /dev/null" \
  "written in checkpoint format 5"

# the advice of the message: the previous checkpoint continues the run
mv truncated/checkpoint.bin.prev truncated/checkpoint.bin
if "$exe" --resume truncated > truncated-2.out 2>&1 &&
   same_records wedge truncated; then
  pass; echo "truncated: resumed from checkpoint.bin.prev: same records"
else
  fail "resume from checkpoint.bin.prev"
fi

if ! (ulimit -f 64) 2> /dev/null; then
  echo "SKIPPED: ulimit -f is not available, no failed-write cases"
else
  # a CSV file over the limit, then resumed without it
  make_slider_prm slider
  "$exe" slider.prm > slider.log 2>&1 || fail "spring-slider run"
  make_slider_prm full
  limited 64 "$exe" full.prm > full.out 2> full.err
  status=$?
  if [ $status -eq 1 ] &&
     one_line_error full.err "full/time-series.csv: File too large" &&
     [ -f full/checkpoint.bin ]; then
    pass
  else
    fail "time-series.csv over the limit (exit $status)"; cat full.err
  fi
  echo "full: $(cat full.err)"
  if "$exe" --resume full > full-2.out 2>&1 &&
     cmp -s slider/events.csv full/events.csv &&
     cmp -s slider/time-series.csv full/time-series.csv; then
    pass; echo "full: resumed without the limit: same events.csv"
  else
    fail "resume after the failed write"
  fi

  # a VTU snapshot over the limit (parameters.prm, about 35 kB, fits)
  make_wedge_prm vtu 5
  limited 48 "$exe" vtu.prm > vtu.out 2> vtu.err
  status=$?
  if [ $status -eq 1 ] &&
     one_line_error vtu.err "vtu/solution/solution-00000.vtu: File too large"; then
    pass
  else
    fail "VTU over the limit (exit $status)"; cat vtu.err
  fi
  echo "vtu: $(cat vtu.err)"

  # a checkpoint over the limit: the finished run resumed rewrites its
  # final checkpoint; the records of the run fit below the limit
  rm -rf ckpt; cp -a wedge ckpt
  largest=$(stat -c %s ckpt/*.csv ckpt/log.txt | sort -n | tail -1)
  limit=$((largest / 1024 + 2))
  if [ $((limit * 1024)) -ge "$(stat -c %s ckpt/checkpoint.bin)" ]; then
    fail "the checkpoint ($(stat -c %s ckpt/checkpoint.bin) bytes) is not above the limit of $limit KiB"
  fi
  sha256sum ckpt/checkpoint.bin ckpt/checkpoint.bin.prev > ckpt.before
  limited $limit "$exe" --resume ckpt > ckpt.out 2> ckpt.err
  status=$?
  if [ $status -eq 1 ] &&
     one_line_error ckpt.err "ckpt/checkpoint.tmp: File too large; the last checkpoint ckpt/checkpoint.bin is unchanged" &&
     sha256sum -c --quiet ckpt.before && [ ! -e ckpt/checkpoint.tmp ]; then
    pass
  else
    fail "checkpoint over the limit (exit $status)"; cat ckpt.err
  fi
  echo "ckpt: $(cat ckpt.err)"
  if "$exe" --resume ckpt > ckpt-2.out 2>&1 && same_records wedge ckpt &&
     cmp -s wedge/checkpoint.bin ckpt/checkpoint.bin; then
    pass; echo "ckpt: resumed without the limit: same records and checkpoint"
  else
    fail "resume after the failed checkpoint"
  fi
fi

# A full disk: the spring-slider in a tmpfs of 128 KiB, where mounting is
# allowed (root); then the space is freed (remounted with 1 MiB) and the
# run resumed.
mkdir -p disk
if ! mount -t tmpfs -o size=128k tmpfs disk 2> /dev/null; then
  echo "SKIPPED: cannot mount a tmpfs here, no full-disk case"
else
  trap 'umount "$work/disk"' EXIT
  [ -f slider/events.csv ] ||
    { make_slider_prm slider; "$exe" slider.prm > slider.log 2>&1; }
  make_slider_prm disk-run disk/run
  "$exe" disk-run.prm > disk-run.out 2> disk-run.err
  status=$?
  if [ $status -eq 1 ] &&
     one_line_error disk-run.err ": No space left on device" &&
     grep -q "^rsfcycle: error: disk/run/" disk-run.err &&
     [ -f disk/run/checkpoint.bin ]; then
    pass
  else
    fail "full disk (exit $status)"; cat disk-run.err
  fi
  echo "disk: $(cat disk-run.err)"
  if mount -o remount,size=1m disk &&
     "$exe" --resume disk/run > disk-run-2.out 2>&1 &&
     cmp -s slider/events.csv disk/run/events.csv &&
     cmp -s slider/time-series.csv disk/run/time-series.csv; then
    pass; echo "disk: space freed, resumed: same events.csv"
  else
    fail "resume after the full disk"
  fi
fi

echo "run-folder integrity: $n_pass passed, $n_fail failed"
[ $n_fail -eq 0 ]
