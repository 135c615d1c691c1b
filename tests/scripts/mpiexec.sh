#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# The MPI launcher of the NAME.mpirun=N tests (tests/CMakeLists.txt): Open
# MPI's mpiexec, allowed to start as root (CI runs as root; Open MPI refuses
# without these two variables) and to start more ranks than there are cores.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
exec mpiexec --oversubscribe "$@"
