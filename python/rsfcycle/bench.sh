# SPDX-License-Identifier: LGPL-2.1-or-later
# Shell helpers of the benchmark scripts that drive a peer's build (the
# shell counterpart of rsfcycle.bench), sourced as
#   . "$ROOT/python/rsfcycle/bench.sh"

# die MESSAGE: "SCRIPT: MESSAGE" on standard error, exit status 2 (a
# missing argument, peer or build).
die() {
    echo "$(basename "$0"): $*" >&2
    exit 2
}

# help_if_asked ARGUMENT: for -h or --help, print the script's header
# comment (line 2 up to the line `set -e...`, without the licence line) and
# exit 0.
help_if_asked() {
    case ${1:-} in -h | --help)
        sed -n '2,/^set -e/p' "$0" | sed '$d; /SPDX-License-Identifier/d; s/^# \{0,1\}//'
        exit 0
        ;;
    esac
}
