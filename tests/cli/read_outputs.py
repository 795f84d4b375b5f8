"""Open a run's HDF5/XDMF and PVTU outputs with ParaView's readers (VTK's
vtkXdmfReader and vtkXMLPUnstructuredGridReader) and check them against the
run's summary.json: one block/piece per layer and subdomain, 2 x (cells of
Omega- + cells of Omega+) cells per cycle, one time step per cycle, and the
same displacement field through both formats.
Usage: pvpython read_outputs.py RESULTS_DIRECTORY"""
import json
import sys

from paraview import servermanager as sm
from paraview.simple import (MergeBlocks, UpdatePipeline, XDMFReader,
                             XMLPartitionedUnstructuredGridReader)

directory = sys.argv[1]
cycles = json.load(open(directory + "/summary.json"))["cycles"]
failures = 0


def check(what, ok):
    global failures
    print("%s: %s" % (what, "yes" if ok else "NO"))
    failures += 0 if ok else 1


xdmf = XDMFReader(FileNames=[directory + "/solution.xdmf"])
xdmf.UpdatePipelineInformation()
check("XDMF time steps are the cycles",
      list(xdmf.TimestepValues) == [float(c["cycle"]) for c in cycles])
for c in cycles:
    cells = 2 * (c["cells_minus"] + c["cells_plus"])
    name = "%s/solution-%02d.pvtu" % (directory, c["cycle"])
    pvtu = sm.Fetch(XMLPartitionedUnstructuredGridReader(FileName=[name]))
    xdmf.UpdatePipeline(float(c["cycle"]))
    blocks = sm.Fetch(xdmf)
    merged = sm.Fetch(MergeBlocks(Input=xdmf, MergePoints=0))
    check("cycle %d: XDMF has 4 pieces" % c["cycle"],
          blocks.GetNumberOfBlocks() == 4)
    check("cycle %d: XDMF and PVTU have %d cells" % (c["cycle"], cells),
          merged.GetNumberOfCells() == cells and pvtu.GetNumberOfCells() == cells)
    for component in (0, 1):
        a = merged.GetPointData().GetArray("displacement").GetRange(component)
        b = pvtu.GetPointData().GetArray("displacement").GetRange(component)
        scale = max(abs(b[0]), abs(b[1]))
        check("cycle %d: displacement %s range the same in both formats" %
              (c["cycle"], "xy"[component]),
              scale > 0 and max(abs(a[0] - b[0]), abs(a[1] - b[1])) <= 1e-6 * scale)
sys.exit(1 if failures else 0)
