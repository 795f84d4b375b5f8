"""Open a run's interface datasets (interface.pvd -> interface-NN.vtu) with
ParaView's readers and check them against the mathematics of the contact
conditions and against the run's interface-NN.csv:
  - one dataset per cycle in interface.pvd, a polyline of line cells that
    joins the multiplier nodes along Sigma from one end to the other;
  - at every node the values of the CSV (float precision);
  - contact_pressure >= 0; an open node (state 0) has jump_normal > 0 and no
    pressure; a closed node (state 1) has jump_normal ~ 0; the complementarity
    contact_pressure * jump_normal ~ 0; glued nodes (state 2) have no jump;
  - at a crack tip the pressure is the compressive part of the gluing
    multiplier's normal component, max(mu_g . normal, 0), not a drop to 0.
With --example1 also what Example 1's loads impose: the left tip (x = -0.5),
where the glue holds the opening faces, carries no pressure; the right tip
(x = 0.5), where the faces are pressed shut, carries a positive one.
Usage: pvpython read_interface.py RESULTS_DIRECTORY [--example1]"""
import csv
import json
import sys
import xml.etree.ElementTree as ET

from paraview import servermanager as sm
from paraview.simple import XMLUnstructuredGridReader
from vtk.util.numpy_support import vtk_to_numpy

directory = sys.argv[1]
example1 = "--example1" in sys.argv
cycles = json.load(open(directory + "/summary.json"))["cycles"]
failures = 0


def check(what, ok):
    global failures
    print("%s: %s" % (what, "yes" if ok else "NO"))
    failures += 0 if ok else 1


files = [d.get("file") for d in ET.parse(directory + "/interface.pvd").iter("DataSet")]
check("interface.pvd lists one dataset per cycle",
      files == ["interface-%02d.vtu" % c["cycle"] for c in cycles])
for c in cycles:
    k = c["cycle"]
    data = sm.Fetch(XMLUnstructuredGridReader(FileName=[directory + "/" + files[k]]))
    pd = data.GetPointData()
    field = {name: vtk_to_numpy(pd.GetArray(name)) for name in
             ("contact_pressure", "normal_traction", "mu_c", "jump_normal",
              "state", "crack_tip", "s", "mu_g", "normal")}
    rows = list(csv.DictReader(l for l in open("%s/interface-%02d.csv" % (directory, k))
                               if not l.startswith("#")))
    by_s = {round(float(r["s"]), 9): r for r in rows}
    n_cells = data.GetNumberOfCells()
    check("cycle %d: %d line cells join the %d nodes" % (k, n_cells, len(rows)),
          n_cells == len(rows) - 1 and
          all(data.GetCellType(i) == 3 for i in range(n_cells)))
    # Each cell's end points are neighbours along Sigma.
    s_sorted = sorted(by_s)
    ends = sorted((round(float(field["s"][2 * i]), 9), round(float(field["s"][2 * i + 1]), 9))
                  for i in range(n_cells))
    check("cycle %d: the cells follow Sigma from end to end" % k,
          ends == [(s_sorted[i], s_sorted[i + 1]) for i in range(len(s_sorted) - 1)])
    scale = max(abs(float(r[key])) for r in rows
                for key in ("u_minus_x", "u_minus_y", "u_plus_x", "u_plus_y"))
    p_scale = max([abs(float(r["mu_c"])) for r in rows] +
                  [abs(float(r["mu_g_y"])) for r in rows] + [1e-300])
    same = positive = open_ok = closed_ok = glued_ok = complementary = tips = True
    n_tips = 0
    for i in range(data.GetNumberOfPoints()):
        r = by_s[round(float(field["s"][i]), 9)]
        p, jump, state = float(field["contact_pressure"][i]), float(field["jump_normal"][i]), int(field["state"][i])
        for name, key in (("contact_pressure", "contact_pressure"), ("mu_c", "mu_c"),
                          ("jump_normal", "jump_normal"), ("normal_traction", "normal_traction")):
            ref = float(r[key])
            same &= abs(float(field[name][i]) - ref) <= 1e-6 * max(abs(ref), 1e-30) + 1e-30
        same &= state == int(r["state"])
        positive &= p >= 0
        if state == 0:
            open_ok &= jump > 0 and p == 0
        elif state == 1:
            closed_ok &= abs(jump) <= 1e-6 * scale
        else:
            glued_ok &= abs(jump) <= 1e-6 * scale
        complementary &= abs(p * jump) <= 1e-6 * p_scale * scale
        if field["crack_tip"][i] == 1:
            n_tips += 1
            mu_g, normal = field["mu_g"][i], field["normal"][i]
            normal_component = float(mu_g[0] * normal[0] + mu_g[1] * normal[1])
            tips &= abs(p - max(normal_component, 0.)) <= 1e-5 * p_scale
    check("cycle %d: the VTU holds the CSV's values" % k, same)
    check("cycle %d: contact pressure >= 0" % k, positive)
    check("cycle %d: open nodes: jump > 0, no pressure" % k, open_ok)
    check("cycle %d: closed nodes: jump ~ 0" % k, closed_ok)
    check("cycle %d: glued nodes: jump ~ 0" % k, glued_ok)
    check("cycle %d: pressure x jump ~ 0" % k, complementary)
    check("cycle %d: crack tips (%d points) carry max(mu_g.nu, 0)" % (k, n_tips), n_tips >= 2 and tips)
    if example1:
        tip = {round(float(r["x"]), 9): float(r["contact_pressure"]) for r in rows}
        check("cycle %d: Example 1: left tip no pressure, right tip pressed" % k,
              tip[-0.5] == 0 and tip[0.5] > 0)
sys.exit(1 if failures else 0)
