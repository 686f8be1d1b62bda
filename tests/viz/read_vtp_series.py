"""Reads ParaView series written by `mechanist animate` with VTK's own XML reader (Debian's
python3-vtk9): every file the .pvd names must load without error, hold the cell arrays with
one value per triangle, and every frame the same parts. Usage: read_vtp_series.py PVD..."""
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def main():
    failures = []
    for pvd in map(Path, sys.argv[1:]):
        steps = ElementTree.parse(pvd).getroot().find("Collection").findall("DataSet")
        if not steps:
            failures.append(f"{pvd}: no time steps")
        times, cells = [], {}
        for step in steps:
            file = pvd.parent / step.get("file")
            reader = vtkXMLPolyDataReader()
            reader.SetFileName(str(file))
            reader.Update()
            data = reader.GetOutput()
            if reader.GetErrorCode() != 0 or data.GetNumberOfCells() == 0:
                failures.append(f"{file}: unreadable or empty")
                continue
            names = ["gap"] if step.get("part") == "1" else ["part", "subassembly", "clash"]
            for name in names:
                array = data.GetCellData().GetArray(name)
                if array is None or array.GetNumberOfTuples() != data.GetNumberOfCells():
                    failures.append(f"{file}: cell array {name} missing or of the wrong length")
            cells.setdefault(step.get("part"), set()).add(data.GetNumberOfCells())
            if step.get("part") == "0":
                times.append(float(step.get("timestep")))
        if times != sorted(times):
            failures.append(f"{pvd}: time steps out of order")
        for part, counts in cells.items():
            if len(counts) != 1:
                failures.append(f"{pvd}: dataset part {part} changes its cell count {counts}")
        print(f"{pvd}: {len(steps)} datasets read")
    for f in failures:
        print(f)
    return 1 if failures else 0

if __name__ == "__main__":
    sys.exit(main())
