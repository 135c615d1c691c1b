# SPDX-License-Identifier: LGPL-2.1-or-later
# Sourced by the HBI peer scripts (seas-bp3 … seas-bp7, peer/run.sh): the pinned
# checkout of HBI (github.com/sozawa94/hbi) outside the repository, our
# patches on it, and its build.
#
#   hbi_checkout_and_build PEER_SRC NICE PATCH...
#
# PEER_SRC (required) is cloned if absent (from HBI_GIT, default GitHub)
# and checked out at HBI_COMMIT; it must be at that commit. A
# clean tree gets the patches applied in order; a changed tree must be
# exactly those patches (compared with a fresh worktree that has them). It
# is built (gfortran via mpifort, -O3 -march=native, under nice NICE) if
# lhbiem is missing or older than a patch. Sets HBI_BIN.
HBI_COMMIT=29b8f905ec5cc4fd83e180da792660ae9825543a   # sozawa94/hbi, 2026-03-06 "Revise input file descriptions"

hbi_checkout_and_build() {
  local src=$1 nice=$2
  shift 2
  local patches=("$@") p
  [ -n "$src" ] || { echo "ERROR: no HBI checkout given (set PEER_SRC)" >&2; exit 2; }
  if [ ! -d "$src/.git" ]; then
    git clone -q "${HBI_GIT:-https://github.com/sozawa94/hbi.git}" "$src"
    git -C "$src" checkout -q "$HBI_COMMIT"
  fi
  local head
  head=$(git -C "$src" rev-parse HEAD)
  if [ "$head" != "$HBI_COMMIT" ]; then
    echo "ERROR: $src is at $head, expected pinned $HBI_COMMIT" >&2; exit 1
  fi
  if [ -z "$(git -C "$src" diff --name-only)" ]; then
    for p in "${patches[@]}"; do git -C "$src" apply "$p"; done
  else
    local tmp expected
    tmp=$(mktemp -d)
    git -C "$src" worktree add -q --detach "$tmp/tree" "$HBI_COMMIT"
    for p in "${patches[@]}"; do git -C "$tmp/tree" apply "$p"; done
    expected=$(git -C "$tmp/tree" diff)
    git -C "$src" worktree remove --force "$tmp/tree"
    rm -rf "$tmp"
    if [ "$(git -C "$src" diff)" != "$expected" ]; then
      echo "ERROR: $src has local changes that are not exactly ${patches[*]##*/}" >&2; exit 1
    fi
  fi
  local stale=0
  [ -x "$src/lhbiem" ] || stale=1
  for p in "${patches[@]}"; do [ "$p" -nt "$src/lhbiem" ] && stale=1; done
  if [ $stale = 1 ]; then
    ( cd "$src" && make clean >/dev/null &&
      nice -n "$nice" make F90="mpifort -fallow-argument-mismatch -ffree-form -ffree-line-length-none -O3 -march=native -fopenmp" \
        > build.log 2>&1 ) || { tail -20 "$src/build.log"; exit 1; }
  fi
  HBI_BIN=$src/lhbiem
}
