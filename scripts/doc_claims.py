"""The numbers README.md and docs/*.md quote, and how to reproduce each.

Read by scripts/check_docs (see its --help). Two tables:

COMMANDS: name -> {"command": a bash command line run in the repository
    root}. {bilayer} is the program ($BILAYER or build/bilayer), {out} an
    empty scratch folder of this command (removed afterwards), {build} the
    build folder. Each command runs once, however many claims read it.

CLAIMS: one dict per quoted number:
    id         unique name (check_docs --only ID)
    doc        the file, relative to the repository root
    pattern    a regular expression with one group, the quoted number; it
               must match the doc exactly once. Whitespace in the doc (line
               breaks included) counts as one space. Q("text {} text")
               escapes the text around {} and puts the number group there.
    command    a name of COMMANDS
    extract    "wall" (the command's wall time, seconds), {"regex": R}
               (group 1 of the first match in stdout and stderr;
               "match": k takes the k-th, "reduce": "max"/"min" all), or
               {"json": "FILE under {out}", "key": "cycles.-1.energy"}
    scale      the measured number times scale is compared (100: percent)
    unit       the quoted number times unit is compared (60: minutes)
    tolerance  ("exact",) counts and iterations; ("rounded",) the quoted
               number is the measured one rounded to the quoted digits;
               ("rel", 1e-3) relative; ("factor", 3) timings
    fast       True when the command takes a few seconds (CI runs these)
    kind       "test_table" (the test table of the claim's doc, docs/developer.md,
               against ctest -N) or
               "ctest_count" (the quoted number of tests), no command

To add a claim: add the command if it is new (give its runs an output
folder under {out}), add the claim, run `scripts/check_docs --only ID` and
write the command, the machine and the date beside the number in the doc.
"""
import re

NUM = r"(\d{1,3}(?: \d{3})+|[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?)"


def Q(text):
    """The regex of TEXT with {} the number group (whitespace collapsed)."""
    before, after = " ".join(text.split()).split("{}")
    return re.escape(before) + NUM + re.escape(after)


def json_key(key, file="r/summary.json"):
    return {"json": file, "key": key}


RUN = '{bilayer} %s --set "Output/Output directory={out}/r" --set "Output/Write VTU=false" > {out}/log'
AS = '--set "Solver/Method=active set" '
COMMANDS = {
    # README (tour, "Converge it"): the paper's run and the one-line converged
    # command against a 16-cycle reference, with wall times.
    "paper_settings": {"command": "scripts/paper_settings"},
    # docs/scenes.md: the paper's three scenes at their default meshes.
    "run_examples": {"command": "scripts/run_examples --output {out}/r"},
    # docs/reproduction.md: Table 1 (theta = 65), meshes 1-4 (a few seconds).
    "table1_4": {"command": RUN % 'parameter_files/table1.prm --set "Mesh/Number of cycles=4"'},
    "table1": {"command": RUN % "parameter_files/table1.prm"},
    "table1_auto_constant_4": {"command": RUN % ('parameter_files/table1.prm --set "Mesh/Number of cycles=4" '
                                                 '--set "Solver/Uzawa step theta=auto" '
                                                 '--set "Solver/Auto theta steps=constant"')},
    "table1_auto": {"command": RUN % 'parameter_files/table1.prm --set "Solver/Uzawa step theta=auto"'},
    "table1_quads_3": {"command": RUN % 'parameter_files/table1_quads.prm --set "Mesh/Number of cycles=3"'},
    # docs/performance.md: the peer (scipy, monolithic P1) and bilayer's triangles on one mesh.
    "peer_16": {"command": "/usr/bin/python3 scripts/peer_reference --single 16"},
    "triangles_16": {"command": RUN % ('parameter_files/partial_closure.prm ' + AS +
                                       '--set "Mesh/Element shape=triangles" '
                                       '--set "Solver/Stopping rule=kkt" --set "Solver/Tolerance=1e-10"')},
    # docs/performance.md: the active set on the Table 1 triangles (KKT 1e-10, as bench_solvers).
    "table1_active_set": {"command": RUN % ('parameter_files/table1.prm ' + AS +
                                            '--set "Solver/Tolerance=1e-10"')},
    # README (tour, "Read G ± dG"): G and dG at the open tip of the main
    # command (one cycle) and of the converged command (12 adaptive Q2 cycles).
    "main_command": {"command": RUN % "parameter_files/partial_closure.prm"},
    "converged_command": {"command": RUN % ('parameter_files/partial_closure.prm ' + AS +
                                            '--set "Mesh/Refinement=adaptive" --set "Mesh/Number of cycles=12" '
                                            '--set "Mesh/Polynomial degree of layer 1=2" '
                                            '--set "Mesh/Polynomial degree of layer 2=2" '
                                            '--set "Solver/Warm start=true"')},
    # docs/outputs.md: the efficiency index of eta on Example 1, Q1, four uniform cycles.
    "mesh_convergence_ex1": {"command": 'scripts/mesh_convergence parameter_files/partial_closure.prm '
                                        '--output {out}/m --set "Mesh/Number of cycles=4" '
                                        '--set "Solver/Method=active set"'},
    # Slow (minutes).
    "mesh_convergence_table1": {"command": "scripts/mesh_convergence parameter_files/table1.prm --output {out}/m"},
    "mesh_convergence_quads": {"command": "scripts/mesh_convergence parameter_files/table1_quads.prm --output {out}/m"},
    "hard_cases": {"command": "scripts/hard_cases --output {out}/h"},
    "work_precision": {"command": "scripts/work_precision --output {out}/w"},
    "crack_growth_end": {"command": "scripts/crack_growth parameter_files/partial_closure.prm "
                                    "--tip end --output {out}/c"},
    # docs/accuracy.md: adaptive rates on the composite ply (a minute each).
    "mesh_convergence_ply_q1": {"command": 'scripts/mesh_convergence parameter_files/composite_ply.prm '
                                           '--reference -2.58217670e-05 --output {out}/m '
                                           '--set "Output/Write VTU=false" --set "Mesh/Number of cycles=16" '
                                           '--set "Mesh/Polynomial degree of layer 1=1" '
                                           '--set "Mesh/Polynomial degree of layer 2=1"'},
    "mesh_convergence_ply_q2": {"command": 'scripts/mesh_convergence parameter_files/composite_ply.prm '
                                           '--reference -2.58217670e-05 --output {out}/m '
                                           '--set "Output/Write VTU=false" --set "Mesh/Number of cycles=18"'},
    # docs/accuracy.md: adaptive rates on the thin film, a thermal bimaterial (a minute each).
    "mesh_convergence_film_q1": {"command": 'scripts/mesh_convergence parameter_files/thin_film.prm '
                                            '--reference 1.5267337820e-02 --output {out}/m '
                                            '--set "Output/Write VTU=false" --set "Solver/Tolerance=1e-10" '
                                            '--set "Mesh/Number of cycles=18" '
                                            '--set "Mesh/Polynomial degree of layer 1=1"'},
    "mesh_convergence_film_q2": {"command": 'scripts/mesh_convergence parameter_files/thin_film.prm '
                                            '--reference 1.5267337820e-02 --output {out}/m '
                                            '--set "Output/Write VTU=false" --set "Solver/Tolerance=1e-10" '
                                            '--set "Mesh/Number of cycles=28"'},
    # docs/geometry.md: the composite ply (issue 32), its own settings (a few seconds).
    "composite_ply": {"command": RUN % "parameter_files/composite_ply.prm"},
    # docs/fracture.md §6 and docs/scenes.md: Example 1 with friction (about a minute).
    "friction_study": {"command": "scripts/friction_study --output {out}/f"},
    # docs/performance.md: the cost of a growth curve (about a minute).
    "bench_growth": {"command": "scripts/bench_growth --no-outputs --repeat 2 --output {out}/b"},
    # docs/cohesive.md: 100 cohesive steps against one static solve with
    # the Newton method (about 20 s, and 90 s at 800 cells).
    "cohesive_bench_320": {"command": "scripts/cohesive_study --bench 320 --output {out}/c320"},
    "cohesive_bench_800": {"command": "scripts/cohesive_study --bench 800 --output {out}/c800"},
    # docs/tour.md: the newcomer's path after the set-up (a few seconds).
    "tour": {"command": "scripts/tour --output {out}/t --bilayer {bilayer}"},
    # docs/scenes.md: the DCB debonding under a rising force (a few seconds).
    "dcb_growth": {"command": '{bilayer} parameter_files/dcb_growth.prm --set "Output/Output directory={out}/r" '
                              '--set "Output/Write VTU=false"'},
}

PAPER = r"paper's settings \(Uzawa, theta = 65, 16 cells\).*?"
QUICK = r"one-line converged command \(12 adaptive Q2 cycles\).*?"
EFFICIENCY = r"^\s*\d+\s+\d+(?:\s+\S+){6}\s+(\S+)\s+\d+\s*$"  # the column efficiency of its table
RATIO = r"energy error \|dPi\|/\|Pi\| (\S+)"

CLAIMS = [
    # docs/developer.md: the counts of the test suite.
    {"id": "tests.count", "doc": "docs/developer.md", "kind": "ctest_count", "fast": True,
     "pattern": Q("ctest knows {} tests"), "tolerance": ("exact",)},
    {"id": "tests.table", "doc": "docs/developer.md", "kind": "test_table", "fast": True},

    # README (tour, "Converge it"), the paper's settings against the converged solution.
    {"id": "readme.paper.energy_error", "doc": "README.md", "fast": True,
     "pattern": Q("the main command's energy error |Pi_h − Pi|/|Pi| is {} %"),
     "command": "paper_settings", "extract": {"regex": PAPER + RATIO}, "scale": 100,
     "tolerance": ("rounded",)},
    {"id": "readme.paper.energy_norm_error", "doc": "README.md", "fast": True,
     "pattern": Q("(an energy-norm error of {} %"),
     "command": "paper_settings", "extract": {"regex": PAPER + r"energy-norm error (\S+)"},
     "scale": 100, "tolerance": ("rounded",)},
    {"id": "readme.paper.opening_next_to_contact", "doc": "README.md", "fast": True,
     "pattern": Q("13–18 % ({} % next to the contact zone)"),
     "command": "paper_settings", "extract": {"regex": r"^\s+\S+\s+\S+\s+\S+\s+(\S+) %$", "reduce": "max"},
     "tolerance": ("rounded",)},
    {"id": "readme.paper.wall", "doc": "README.md", "fast": True,
     "pattern": Q("run: {} s wall time, most of it the start of the process"),
     "command": "paper_settings", "extract": {"regex": PAPER + r"dofs\s+(\S+) s"},
     "tolerance": ("factor", 3)},
    {"id": "readme.converged.energy_error", "doc": "README.md", "fast": True,
     "pattern": Q("an energy error |Pi_h − Pi|/|Pi| of {} (energy-norm error"),
     "command": "paper_settings", "extract": {"regex": QUICK + RATIO}, "tolerance": ("rounded",)},
    {"id": "readme.converged.energy_norm_error", "doc": "README.md", "fast": True,
     "pattern": Q("(energy-norm error {}; against a 16-cycle run)"),
     "command": "paper_settings", "extract": {"regex": QUICK + r"energy-norm error (\S+)"},
     "tolerance": ("rounded",)},
    {"id": "readme.converged.dofs", "doc": "README.md", "fast": True,
     "pattern": Q("in 12 cycles, {} dofs and"),
     "command": "paper_settings", "extract": {"regex": QUICK + r"(\d+) dofs"}, "tolerance": ("exact",)},
    {"id": "readme.converged.wall", "doc": "README.md", "fast": True,
     "pattern": Q("dofs and {} s of wall time with every cycle written"),
     "command": "paper_settings", "extract": {"regex": QUICK + r"dofs\s+(\S+) s"},
     "tolerance": ("factor", 3)},

    # README (tour, "Read G ± dG"), G ± dG of the main and the converged command.
    {"id": "readme.tour.G_main", "doc": "README.md", "fast": True,
     "pattern": Q("`\"converged\": true`, gives G = {} ± 7.3e-08 at the open"),
     "command": "main_command", "extract": json_key("cycles.-1.crack_tips.0.G"),
     "tolerance": ("rounded",)},
    {"id": "readme.tour.dG_main", "doc": "README.md", "fast": True,
     "pattern": Q("gives G = 3.8428e-07 ± {} at the open"),
     "command": "main_command", "extract": json_key("cycles.-1.crack_tips.0.G_error"),
     "tolerance": ("rounded",)},
    {"id": "readme.tour.G_converged", "doc": "README.md", "fast": True,
     "pattern": Q("the converged command above gives G = {} ± 2.3e-10 there"),
     "command": "converged_command", "extract": json_key("cycles.-1.crack_tips.0.G"),
     "tolerance": ("rounded",)},
    {"id": "readme.tour.dG_converged", "doc": "README.md", "fast": True,
     "pattern": Q("the converged command above gives G = 4.8523e-07 ± {} there"),
     "command": "converged_command", "extract": json_key("cycles.-1.crack_tips.0.G_error"),
     "tolerance": ("rounded",)},

    # docs/tour.md, scripts/tour.
    {"id": "tour.G", "doc": "docs/tour.md", "fast": True,
     "pattern": Q("The open tip at x = -0.6: G = {} ± 3.9e-10"),
     "command": "tour", "extract": {"regex": r"tip 1 \(x = -0.6\): G = (\S+) ±"},
     "tolerance": ("rounded",)},
    {"id": "tour.dG", "doc": "docs/tour.md", "fast": True,
     "pattern": Q("G = 8.0086e-07 ± {} after 11 cycles"),
     "command": "tour", "extract": {"regex": r"tip 1 \(x = -0.6\): G = \S+ ± (\S+)"},
     "tolerance": ("rounded",)},
    {"id": "tour.cycles", "doc": "docs/tour.md", "fast": True,
     "pattern": Q("± 3.9e-10 after {} cycles"),
     "command": "tour", "extract": {"regex": r"tip 1 .* after (\d+) cycles"},
     "tolerance": ("exact",)},
    {"id": "tour.dofs", "doc": "docs/tour.md", "fast": True,
     "pattern": Q("after 11 cycles ({} dofs, adaptive"),
     "command": "tour", "extract": {"regex": r"tip 1 .* cycles, (\d+) dofs"},
     "tolerance": ("exact",)},
    {"id": "tour.converge_wall", "doc": "docs/tour.md", "fast": True,
     "pattern": Q("Q2) in {} s (2-core x86_64 VM"),
     "command": "tour", "extract": {"regex": r"step 2, converge:.*\n\s+(\S+) s"},
     "tolerance": ("factor", 3)},
    {"id": "tour.closed_G", "doc": "docs/tour.md", "fast": True,
     "pattern": Q("is closed: G = {} ± 5.9e-10"),
     "command": "tour", "extract": {"regex": r"tip 2 \(x = 0.4\): G = (\S+) ±"},
     "tolerance": ("rounded",)},
    {"id": "tour.sweep_wall", "doc": "docs/tour.md", "fast": True,
     "pattern": Q("two at a time, in {} s (2-core"),
     "command": "tour", "extract": {"regex": r"step 3, sweep:.*\n\s+(\S+) s"},
     "tolerance": ("factor", 3)},
    {"id": "tour.sweep_G_28", "doc": "docs/tour.md", "fast": True,
     "pattern": Q("falls from {} (E_2 = 28)"),
     "command": "tour", "extract": {"regex": r"^\| 1 \| 28 \| 0 \|(?: [^|]* \|){5} (\S+) \|"},
     "tolerance": ("rounded",)},
    {"id": "tour.sweep_G_224", "doc": "docs/tour.md", "fast": True,
     "pattern": Q("to {} (E_2 = 224)"),
     "command": "tour", "extract": {"regex": r"^\| 4 \| 224 \| 0 \|(?: [^|]* \|){5} (\S+) \|"},
     "tolerance": ("rounded",)},
    {"id": "tour.total_wall", "doc": "docs/tour.md", "fast": True,
     "pattern": Q("steps 2–4 took {} s of machine time"),
     "command": "tour", "extract": {"regex": r"tour: steps 2-4 in (\S+) s"},
     "tolerance": ("factor", 3)},

    # docs/scenes.md, scripts/run_examples.
    {"id": "readme.run_examples.iterations_1", "doc": "docs/scenes.md", "fast": True,
     "pattern": r"it printed (\d+), \d+ and \d+ iterations",
     "command": "run_examples", "extract": {"regex": r"^partial_closure\s+(\d+)"}, "tolerance": ("exact",)},
    {"id": "readme.run_examples.iterations_2", "doc": "docs/scenes.md", "fast": True,
     "pattern": r"it printed \d+, (\d+) and \d+ iterations",
     "command": "run_examples", "extract": {"regex": r"^full_opening\s+(\d+)"}, "tolerance": ("exact",)},
    {"id": "readme.run_examples.iterations_3", "doc": "docs/scenes.md", "fast": True,
     "pattern": r"it printed \d+, \d+ and (\d+) iterations",
     "command": "run_examples", "extract": {"regex": r"^partial_closure_linear\s+(\d+)"},
     "tolerance": ("exact",)},

    # docs/outputs.md, the efficiency index of eta (scripts/mesh_convergence).
    {"id": "readme.eta.efficiency_min", "doc": "docs/outputs.md", "fast": True,
     "pattern": Q("Its efficiency index eta / e_h on Example 1, Q1, uniform refinement is {}–"),
     "command": "mesh_convergence_ex1", "extract": {"regex": EFFICIENCY, "reduce": "min"},
     "tolerance": ("rounded",)},
    {"id": "readme.eta.efficiency_max", "doc": "docs/outputs.md", "fast": True,
     "pattern": r"uniform refinement is \d\.\d+–" + Q("{} on its four cycles"),
     "command": "mesh_convergence_ex1", "extract": {"regex": EFFICIENCY, "reduce": "max"},
     "tolerance": ("rounded",)},

    # docs/reproduction.md, Table 1 (theta = 65) and theta = auto.
] + [
    {"id": "reproduction.table1.iterations_%d" % k, "doc": "docs/reproduction.md", "fast": k < 4,
     "pattern": r"\| %d \| %d \|(?: [^|]+ \|){8} (\d+) \| %d \|" % (p, m, paper),
     "command": "table1_4" if k < 4 else "table1",
     "extract": json_key("cycles.%d.iterations" % k), "tolerance": ("exact",)}
    for k, (p, m, paper) in enumerate([(12, 32, 843), (24, 48, 1164), (48, 80, 1416),
                                       (96, 144, 1909), (200, 256, 2402)])
] + [
    {"id": "reproduction.table1.energy_%d" % k, "doc": "docs/reproduction.md", "fast": k < 4,
     "pattern": r"\| %d \| %d \|(?: [^|]+ \|){10} (-\d\.\d+e-06) \|" % (p, m),
     "command": "table1_4" if k < 4 else "table1",
     "extract": json_key("cycles.%d.energy" % k), "tolerance": ("rounded",)}
    for k, (p, m) in enumerate([(12, 32), (24, 48), (48, 80), (96, 144), (200, 256)])
] + [
    {"id": "reproduction.theta_auto_constant.iterations_%d" % k, "doc": "docs/reproduction.md",
     "fast": True, "pattern": r"converged on all five Table 1 meshes \(" + r"\d+, " * k + r"(\d+)",
     "command": "table1_auto_constant_4", "extract": json_key("cycles.%d.iterations" % k),
     "tolerance": ("exact",)}
    for k in range(4)
] + [
    {"id": "reproduction.theta_auto_adaptive.iterations_%d" % k, "doc": "docs/reproduction.md",
     "fast": True, "pattern": r"with the adaptive steps \(the default\) in " + r"\d+, " * min(k, 3)
     + (r"\d+ and " if k == 4 else "") + r"(\d+)",
     "command": "table1_auto", "extract": json_key("cycles.%d.iterations" % k),
     # The adaptive (Barzilai-Borwein) steps follow the last bits of the
     # subdomain solves, which differ between CPUs (OpenBLAS's kernels).
     "tolerance": ("rel", 0.25)}
    for k in range(5)
] + [
    {"id": "reproduction.quads.iterations_%d" % k, "doc": "docs/reproduction.md", "fast": True,
     "pattern": r"\| %d \| %d \|(?: [^|]+ \|){3} (\d+) \| %d \|" % (p, m, paper),
     "command": "table1_quads_3", "extract": json_key("cycles.%d.iterations" % k),
     "tolerance": ("exact",)}
    for k, (p, m, paper) in enumerate([(13, 48, 843), (25, 96, 1164), (49, 192, 1416)])
] + [
    {"id": "performance.peer.energy_16", "doc": "docs/performance.md", "fast": False,
     "pattern": Q("the peer's energy at N = 16 is {}"), "command": "peer_16",
     "extract": {"regex": r"energy Pi = (\S+)"}, "tolerance": ("rel", 1e-10)},
    {"id": "performance.peer.triangles_16", "doc": "docs/performance.md", "fast": False,
     "pattern": Q("bilayer's on the same triangles {}"), "command": "triangles_16",
     "extract": json_key("cycles.-1.energy"), "tolerance": ("rel", 1e-9)},
] + [
    {"id": "performance.active_set.newton_triangles_%d" % k, "doc": "docs/performance.md", "fast": True,
     "pattern": r"\*\*Newton steps\*\* " + r"\d+, " * k + r"(\d+)",
     "command": "table1_active_set", "extract": json_key("cycles.%d.iterations" % k),
     "tolerance": ("exact",)}
    for k in range(5)
] + [
    # docs/accuracy.md, the rates of adaptive Q1 and Q2 on the composite ply (slow).
    {"id": "accuracy.ply.q1_rate", "doc": "docs/accuracy.md", "fast": False,
     "pattern": Q("| 16, 625 668 | N^{} (cycles 8–15)"), "command": "mesh_convergence_ply_q1",
     "extract": {"regex": r"least squares over cycles \d+-\d+: e_h ~ N\^(\S+) "},
     "tolerance": ("rounded",)},
    {"id": "accuracy.ply.q2_rate", "doc": "docs/accuracy.md", "fast": False,
     "pattern": Q("| 18, 139 724 | N^{} (cycles 9–17)"), "command": "mesh_convergence_ply_q2",
     "extract": {"regex": r"least squares over cycles \d+-\d+: e_h ~ N\^(\S+) "},
     "tolerance": ("rounded",)},
    {"id": "accuracy.ply.q2_dofs", "doc": "docs/accuracy.md", "fast": False,
     "pattern": Q("| 18, {} | N^-1.06"), "command": "mesh_convergence_ply_q2",
     "extract": {"regex": r"^\s*17\s+(\d+)\s"}, "tolerance": ("exact",)},

    # docs/accuracy.md, the rates of adaptive Q1 and Q2 on the thin film (slow).
    {"id": "accuracy.film.q1_rate", "doc": "docs/accuracy.md", "fast": False,
     "pattern": Q("| 18, 297 906 | N^{} (cycles 9–17)"), "command": "mesh_convergence_film_q1",
     "extract": {"regex": r"least squares over cycles \d+-\d+: e_h ~ N\^(\S+) "},
     "tolerance": ("rounded",)},
    {"id": "accuracy.film.q2_rate", "doc": "docs/accuracy.md", "fast": False,
     "pattern": Q("| 28, 571 494 | N^{} (cycles 14–27)"), "command": "mesh_convergence_film_q2",
     "extract": {"regex": r"least squares over cycles \d+-\d+: e_h ~ N\^(\S+) "},
     "tolerance": ("rounded",)},
    {"id": "accuracy.film.q2_dofs", "doc": "docs/accuracy.md", "fast": False,
     "pattern": Q("| 28, {} | N^-1.09"), "command": "mesh_convergence_film_q2",
     "extract": {"regex": r"^\s*27\s+(\d+)\s"}, "tolerance": ("exact",)},

    # docs/geometry.md, the composite ply on an aluminium sheet.
    {"id": "geometry.composite_ply.dofs", "doc": "docs/geometry.md", "fast": True,
     "pattern": Q("2026-12-03): {} dofs on the last cycle"), "command": "composite_ply",
     "extract": json_key("cycles.-1.dofs"), "tolerance": ("exact",)},
    {"id": "geometry.composite_ply.energy", "doc": "docs/geometry.md", "fast": True,
     "pattern": Q("energy Pi = {} GPa mm²"), "command": "composite_ply",
     "extract": json_key("cycles.-1.energy"), "tolerance": ("rounded",)},
    {"id": "geometry.composite_ply.G_open", "doc": "docs/geometry.md", "fast": True,
     "pattern": Q("G = {} GPa mm (0.0995 J/m²)"), "command": "composite_ply",
     "extract": json_key("cycles.-1.crack_tips.0.G"), "tolerance": ("rounded",)},
    {"id": "geometry.composite_ply.G_closed", "doc": "docs/geometry.md", "fast": True,
     "pattern": Q("x = −10 and {} at the closed tip"), "command": "composite_ply",
     "extract": json_key("cycles.-1.crack_tips.1.G"), "tolerance": ("rounded",)},

    # Timings of the study scripts (slow: minutes).
    {"id": "reproduction.table1.time", "doc": "docs/reproduction.md", "fast": False,
     "pattern": Q("(P1 triangles; about {} s,"), "command": "mesh_convergence_table1",
     "extract": "wall", "tolerance": ("factor", 2)},
    {"id": "reproduction.quads.time", "doc": "docs/reproduction.md", "fast": False,
     "pattern": Q("12 · 2^k cells along Sigma; about {} s on"), "command": "mesh_convergence_quads",
     "extract": "wall", "tolerance": ("factor", 2)},
    {"id": "readme.hard_cases.time", "doc": "docs/scripts.md", "fast": False,
     "pattern": Q("cleanly refused/stopped ([docs/robustness.md](robustness.md)); {} s"),
     "command": "hard_cases", "extract": "wall", "tolerance": ("factor", 2)},
    {"id": "robustness.hard_cases.time", "doc": "docs/robustness.md", "fast": False,
     "pattern": Q("60 runs in 140 s on 2026-11-29; {} s on 2026-12-02"), "command": "hard_cases",
     "extract": {"regex": r"\d+ runs in (\d+) s"}, "tolerance": ("factor", 2)},
    {"id": "readme.work_precision.time", "doc": "docs/scripts.md", "fast": False,
     "pattern": Q("gnuplot PNGs ([docs/accuracy.md](accuracy.md)); {} s"),
     "command": "work_precision", "extract": "wall", "tolerance": ("factor", 2)},
    {"id": "accuracy.work_precision.time", "doc": "docs/accuracy.md", "fast": False,
     "pattern": Q("Total wall time of the study: 216 s (2026-11-29; {} s on 2026-12-02"), "command": "work_precision",
     "extract": {"regex": r"Total wall time of the study: (\d+) s"}, "tolerance": ("factor", 2)},
    {"id": "readme.work_precision.one_percent_time", "doc": "docs/discretisation.md", "fast": False,
     "pattern": Q("docs/accuracy.md; {} s on 2026-12-02, the same VM"), "command": "work_precision",
     "extract": {"regex": r"^\| adaptive Q1, active set \|(?: [^|]+ \|){8} (\S+) \|"},
     "tolerance": ("factor", 2)},
    {"id": "accuracy.work_precision.one_percent_time", "doc": "docs/accuracy.md", "fast": False,
     "pattern": Q("2.6e5 DoFs and 13 s (measured; {} s on 2026-12-02"), "command": "work_precision",
     "extract": {"regex": r"^\| adaptive Q1, active set \|(?: [^|]+ \|){8} (\S+) \|"},
     "tolerance": ("factor", 2)},
    {"id": "readme.work_precision.one_percent_dofs", "doc": "docs/discretisation.md", "fast": False,
     "pattern": Q("and 1 % with {} DoFs in 13 s"), "command": "work_precision",
     "extract": {"regex": r"^\| adaptive Q1, active set \|(?: [^|]+ \|){7} (\S+) \|"},
     "tolerance": ("rounded",)},
    # docs/fracture.md §6, "Example 1 with friction" (slow: a minute).
    {"id": "fracture.friction.G_closed_F05", "doc": "docs/fracture.md", "fast": False,
     "pattern": Q("falls steadily with F: to {} of its frictionless value at F = 0.5"),
     "command": "friction_study",
     "extract": {"regex": r"^\| Coulomb F = 0\.5 \|(?: [^|]+ \|){6} (\S+) \|"},
     "tolerance": ("rounded",)},
    {"id": "fracture.friction.G_closed_F08", "doc": "docs/fracture.md", "fast": False,
     "pattern": Q("(the shipped scene's coefficient) and to {} at F = 0.8"),
     "command": "friction_study",
     "extract": {"regex": r"^\| Coulomb F = 0\.8 \|(?: [^|]+ \|){6} (\S+) \|"},
     "tolerance": ("rounded",)},
    {"id": "fracture.friction.stick_from", "doc": "docs/fracture.md", "fast": False,
     "pattern": Q("From F = {} on, the nodes next to the tip stick"), "command": "friction_study",
     "extract": {"regex": r"sticks from F = (\S+) on"}, "tolerance": ("exact",)},
    {"id": "readme.friction.stick_from", "doc": "docs/scenes.md", "fast": False,
     "pattern": Q("from F = {} on (128 cells) the faces next to it stick"),
     "command": "friction_study",
     "extract": {"regex": r"sticks from F = (\S+) on"}, "tolerance": ("exact",)},
    {"id": "fracture.friction.open_tip", "doc": "docs/fracture.md", "fast": False,
     "pattern": Q("G there changes by at most {} % over the Coulomb runs"),
     "command": "friction_study",
     "extract": {"regex": r"open tip over the Coulomb runs: (\S+) %"}, "tolerance": ("rounded",)},
    {"id": "fracture.friction.tresca_open_tip", "doc": "docs/fracture.md", "fast": False,
     "pattern": Q("(to {} of its frictionless value at g = 0.02)"), "command": "friction_study",
     "extract": {"regex": r"Tresca g = 0\.02: G at the open tip (\S+) of the frictionless"},
     "tolerance": ("rounded",)},
    {"id": "fracture.friction.time", "doc": "docs/fracture.md", "fast": False,
     "pattern": Q("(15 runs in {} s; 2-core x86_64 dev VM"), "command": "friction_study",
     "extract": {"regex": r"bilayer runs in (\d+) s"}, "tolerance": ("factor", 2)},
    {"id": "cohesive.bench_320.ratio", "doc": "docs/cohesive.md", "fast": False,
     "pattern": Q("with `Method = newton` 8.0 s, **{} times** the static solve"),
     "command": "cohesive_bench_320",
     "extract": {"regex": r"newton: 100 cohesive steps \S+ s \((\S+) times"},
     "tolerance": ("factor", 2)},
    {"id": "cohesive.bench_320.secant_iterations", "doc": "docs/cohesive.md", "fast": False,
     "pattern": Q("**10.5 times** the static solve ({} secant"),
     "command": "cohesive_bench_320",
     "extract": {"regex": r"newton: .*?\((?:\S+) times; (\d+) secant iterations"},
     "tolerance": ("exact",)},
    {"id": "cohesive.bench_800.ratio", "doc": "docs/cohesive.md", "fast": False,
     "pattern": Q("the 100 steps 49.9 s, **{} times** (102"),
     "command": "cohesive_bench_800",
     "extract": {"regex": r"newton: 100 cohesive steps \S+ s \((\S+) times"},
     "tolerance": ("factor", 2)},
    {"id": "performance.growth.ratio", "doc": "docs/performance.md", "fast": False,
     "pattern": Q("On the otherwise idle machine (ratio {}, the performance.growth.ratio"),
     "command": "bench_growth", "extract": {"regex": r"wall \(b\) / wall \(a\) = (\S+)"},
     "tolerance": ("factor", 1.5)},
    {"id": "readme.dcb_growth.onset", "doc": "docs/scenes.md", "fast": True,
     "pattern": Q("the crack starts at the exact onset λ_c ≈ {} and runs"), "command": "dcb_growth",
     "extract": {"regex": r"unstable growth at (?:lambda =|load factor) (\S+) from"}, "tolerance": ("rounded",)},
    {"id": "readme.dcb_growth.end", "doc": "docs/scenes.md", "fast": True,
     "pattern": Q("runs unstably at that load to x = {}, one cell"), "command": "dcb_growth",
     "extract": {"regex": r"unstable growth at (?:lambda =|load factor) \S+ from crack length \S+ to (\S+) "},
     "tolerance": ("rounded",)},
    {"id": "readme.dcb_growth.steps", "doc": "docs/scenes.md", "fast": True,
     "pattern": Q("can no longer be resolved ({} steps in"), "command": "dcb_growth",
     "extract": {"regex": r"^growth: (\d+) steps"}, "tolerance": ("exact",)},
    {"id": "readme.dcb_growth.time", "doc": "docs/scenes.md", "fast": True,
     "pattern": Q("steps in {} s with `Write VTU = false`, 2-core x86_64 VM"), "command": "dcb_growth",
     "extract": "wall", "tolerance": ("factor", 3)},
    {"id": "fracture.crack_growth.time", "doc": "docs/fracture.md", "fast": False,
     "pattern": Q("fracture.crack_growth.time`): {} s; before the cells"), "command": "crack_growth_end",
     "extract": "wall", "tolerance": ("factor", 2)},
]
