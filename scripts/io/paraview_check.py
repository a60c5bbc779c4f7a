"""Check that ParaView reads what `SORT 'VTK'` writes.

Run with ParaView's Python (Debian: `apt-get install paraview`):

    cd scripts/io && gibi export_plate.dgibi    # writes out/ here
    pvpython paraview_check.py out/plate.vtu [VECTOR]
    pvpython paraview_check.py out/plate.pvd

(add --force-offscreen-rendering to pvpython on a machine with no display).

For a .vtu it prints the point and cell counts and every array with its
number of components; with VECTOR (a point array name such as DEPL) it
also applies Warp By Vector, the filter the 3-component displacement
vectors are written for, and prints the warped bounds (give it a vector:
ParaView 5.11 aborts when asked to warp by a scalar). For a .pvd it prints the time steps ParaView
sees. Exits 1 if ParaView reads no points. Not part of CI: ParaView is a
large package; the Rust tests parse the same files themselves.
"""

import sys

from paraview import simple


def describe(source):
    source.UpdatePipeline()
    info = source.GetDataInformation()
    print("points", info.GetNumberOfPoints())
    print("cells", info.GetNumberOfCells())
    for kind, arrays in (("point", source.PointData), ("cell", source.CellData)):
        for name in arrays.keys():
            print(kind, "array", name, "components", arrays[name].GetNumberOfComponents())
    return info.GetNumberOfPoints()


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    path = sys.argv[1]
    if path.endswith(".pvd"):
        reader = simple.PVDReader(FileName=path)
        print("times", list(reader.TimestepValues))
    else:
        reader = simple.XMLUnstructuredGridReader(FileName=[path])
    n = describe(reader)
    if len(sys.argv) > 2:
        warp = simple.WarpByVector(Input=reader)
        warp.Vectors = ["POINTS", sys.argv[2]]
        warp.UpdatePipeline()
        bounds = warp.GetDataInformation().GetBounds()
        print("warped bounds", ["%.6g" % b for b in bounds])
    return 0 if n > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
