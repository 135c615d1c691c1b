# SPDX-License-Identifier: LGPL-2.1-or-later
"""Headless ParaView picture of a 2D run's mesh, coloured by a field.

Usage: python3 -m rsfcycle.paraview screenshot RUN OUT.png [FIELD] (runs
  this script as xvfb-run -a pvbatch mesh_screenshot.py RUN OUT.png FIELD)

Reads RUN/solution.pvd (first snapshot), shows the cells with their edges,
coloured by FIELD (default material_id; deal.II writes cell data as point
data), looking at the x-y plane, and writes OUT.png. This is the picture
of doc/mesh-file.md (the laboratory wedge from a gmsh file).
"""
import sys

from paraview.simple import (ColorBy, CreateView, GetColorTransferFunction,
                             GetScalarBar, PVDReader, SaveScreenshot, Show)


def main(argv):
    """Draw RUN's mesh into OUT.png; argv = [RUN, OUT.png, FIELD?]."""
    if len(argv) not in (2, 3):
        print(__doc__)
        return 2
    rundir, out = argv[0], argv[1]
    field = argv[2] if len(argv) > 2 else "material_id"
    reader = PVDReader(FileName=rundir + "/solution.pvd")
    reader.UpdatePipeline(reader.TimestepValues[0] if reader.TimestepValues
                          else 0.0)
    view = CreateView("RenderView")
    view.ViewSize = [1400, 520]
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    shown = Show(reader, view)
    shown.Representation = "Surface With Edges"
    shown.EdgeColor = [0.2, 0.2, 0.2]
    ColorBy(shown, ("POINTS", field))
    lut = GetColorTransferFunction(field)
    lut.ApplyPreset("Cool to Warm", True)
    shown.RescaleTransferFunctionToDataRange(True, False)
    shown.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.TitleColor = [0, 0, 0]
    bar.LabelColor = [0, 0, 0]
    bounds = reader.GetDataInformation().GetBounds()
    centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, 0]
    view.CameraPosition = [centre[0], centre[1],
                           10 * (bounds[1] - bounds[0])]
    view.CameraFocalPoint = centre
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.6 * max(bounds[3] - bounds[2],
                                         (bounds[1] - bounds[0]) * 520 / 1400)
    SaveScreenshot(out, view, ImageResolution=[1400, 520])
    print("wrote", out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
