# SPDX-License-Identifier: LGPL-2.1-or-later
"""Scripts for ParaView's Python (pvbatch), run by rsfcycle.paraview: they
import paraview.simple and are not imported by the package itself."""
