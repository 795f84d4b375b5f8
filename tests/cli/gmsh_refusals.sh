#!/usr/bin/env bash
# Bad Gmsh scenes: each must end with exactly one line "bilayer: error: ..."
# on stderr naming the file (Geometry/Gmsh file) and the group, the entity,
# the statement or the entry, a non-zero exit, no backtrace and no output
# directory. Variants of parameter_files/two_cracks.{geo,prm}:
# - the physical groups: a missing or misnamed group, a crack that reaches
#   the end of Sigma on a clamped part or covering all of Sigma (and an
#   edge crack whose mouth is free: accepted, and named by --check-geometry),
#   a subdomain without a clamped part, a Sigma that does
#   not separate the subdomains, a traction on a part the file does not
#   have, a .geo that gmsh cannot mesh, a missing file, a .msh of another
#   format;
# - scene files that run programs or write files (SystemCall, Printf > file,
#   Save, Plugin Run, writing options, computed Include paths, also inside an
#   Include'd file): refused before gmsh runs, the command not run; with
#   --allow-gmsh-commands they run;
# - group names as gmsh reports them (not from comments; from Includes and
#   StrCat: the same energy as two_cracks.prm itself), and the options that
#   bilayer overrides (Mesh.Binary, Mesh.MshFileVersion, Mesh.ElementOrder:
#   the same energy);
# - cells and edges outside the groups bilayer understands (a surface in no
#   group or an unknown one, a cell in two, a curve in Sigma and crack or in
#   two parts, a boundary part inside the mesh, same-name groups and cells
#   of physical tag 0 in a .msh, nodes off the plane);
# - gmsh that runs too long (a scene that loops, a gmsh that hangs: the time
#   limit; SIGTERM and SIGKILL of bilayer end gmsh and SIGTERM removes the
#   temporary directory), gmsh that exits 0 without a mesh;
# - .msh files with a corrupt tag count or without $PhysicalNames, names that
#   cannot name an entry;
# - scripts/check_geo (bilayer --check-geometry) on a hostile scene;
#   bilayer --check-geometry on a quadrilateral and a triangle scene (the
#   groups, cells and crack pieces, PASS), on a scene of three regions (each
#   region and interface 2) and on a scene without Omega+ (one error line).
# Usage: gmsh_refusals.sh BILAYER PARAMETER_FILES_DIRECTORY
set -u
bilayer=$(realpath "$1")
source_dir=$(realpath "$2")
check_geo=$source_dir/../scripts/check_geo
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
mkdir tmp
export TMPDIR=$work/tmp
failures=0

# report NAME WHY: one result line.
report() {
  if [[ -n $2 ]]; then
    echo "$1: no ($2)"
    cat stderr 2>/dev/null
    failures=$((failures + 1))
  else
    echo "$1: yes"
  fi
}

# running PID: the process exists and is no zombie.
running() {
  local state
  state=$(ps -o stat= -p "$1" 2> /dev/null) && [[ $state != Z* ]]
}
# still_running PID: whether the process still runs after up to 5 s (a
# loaded machine may take a while to end and reap a killed process).
still_running() {
  local _
  for _ in $(seq 100); do
    running "$1" || return 1
    sleep 0.05
  done
  return 0
}

# refuse NAME EXPECTED-FRAGMENT [--set ...]: scene.prm (scene.geo) refused
# (bilayer run with PATH=$run_path where set).
refuse() {
  local name=$1 expect=$2
  shift 2
  PATH=${run_path:-$PATH} "$bilayer" scene.prm --set "Output/Output directory=out" \
    "$@" > stdout 2> stderr
  local rc=$? why=""
  [[ $rc -ne 0 ]] || why="exit status 0"
  [[ $(wc -l < stderr) -eq 1 ]] || why="$why; $(wc -l < stderr) lines on stderr"
  grep -qF "bilayer: error: " stderr || why="$why; no 'bilayer: error:'"
  grep -qF -- "$expect" stderr || why="$why; '$expect' not named"
  ! grep -qiE "stacktrace|terminate called|^-{5,}" stderr || why="$why; backtrace"
  [[ ! -e out ]] || why="$why; output directory written"
  [[ -z $(ls tmp) ]] || why="$why; temporary directory left: $(ls tmp)"
  report "$name" "$why"
  rm -rf out tmp/*
}

# case_ NAME EXPECTED-FRAGMENT GEO-SED-SCRIPT [--set ...]: the scene with
# two_cracks.geo edited by the sed script.
case_() {
  local name=$1 expect=$2 edit=$3
  shift 3
  sed "$edit" "$source_dir/two_cracks.geo" > scene.geo
  sed 's/two_cracks.geo/scene.geo/' "$source_dir/two_cracks.prm" > scene.prm
  refuse "$name" "$expect" "$@"
}

# case3_ NAME EXPECTED-FRAGMENT GEO-SED-SCRIPT [--set ...]: the scene of
# three regions parameter_files/ply_drop.{geo,prm} with its .geo edited.
case3_() {
  local name=$1 expect=$2 edit=$3
  shift 3
  sed "$edit" "$source_dir/ply_drop.geo" > scene.geo
  sed 's/ply_drop.geo/scene.geo/' "$source_dir/ply_drop.prm" > scene.prm
  refuse "$name" "$expect" "$@"
}

# energy FILE.prm [ARGS]: the energy of cycle 0 of a successful run ("" else).
energy() {
  local prm=$1
  shift
  rm -rf run_out
  if "$bilayer" "$prm" --set "Output/Output directory=run_out" "$@" \
       > run_stdout 2> run_stderr; then
    grep -o '"energy": [^,]*' run_out/summary.json | head -1
  fi
  rm -rf run_out
}

# accept NAME [ARGS]: scene.prm runs and gives two_cracks.prm's energy.
accept() {
  local name=$1
  shift
  local got why=""
  got=$(energy scene.prm "$@")
  [[ -n $got ]] || why="run failed: $(cat run_stderr)"
  [[ -z $got || $got == "$reference" ]] || why="$got, two_cracks.prm: $reference"
  [[ -z $(ls tmp) ]] || why="$why; temporary directory left: $(ls tmp)"
  report "$name" "$why"
}

cp "$source_dir/two_cracks.geo" "$source_dir/two_cracks.prm" .
reference=$(energy two_cracks.prm)
[[ -n $reference ]] || { echo "two_cracks.prm does not run"; cat run_stderr; exit 1; }
echo "two_cracks.prm: $reference"

# --- The physical groups.
case_ "missing Omega- group" "scene.geo': no physical surface named 'Omega-'" \
  's/Physical Surface("Omega-")/Physical Surface("lower")/'
case_ "misnamed crack and Sigma groups" "no physical curve named 'Sigma'" \
  's/Physical Curve("Sigma")/Physical Curve("glued")/; s/Physical Curve("crack")/Physical Curve("debond")/' \
  --set "Geometry/Clamped sides=left, right"
case_ "misnamed clamped part" "Clamped sides" 's/^$//' \
  --set "Geometry/Clamped sides=left, rigth"
case_ "traction on an unknown part" "Traction on hole" 's/^$//' \
  --set "Loads/Layer 1/Traction on hole=0; 1"
# An edge crack (the crack group reaching the end of Sigma at x = -2): refused
# where that end lies on a clamped part, accepted where it is free; a crack
# group covering all of Sigma refused.
edge_crack='s/Physical Curve("Sigma") = {11, 13, 15};/Physical Curve("Sigma") = {13, 15};/; s/Physical Curve("crack") = {12, 14};/Physical Curve("crack") = {11, 12, 14};/'
case_ "crack reaching the end of Sigma on Gamma_D" \
  "a crack piece reaches the end (-2, 0) of Sigma, which lies on the clamped part 'left' (Geometry/Clamped sides)" \
  "$edge_crack"
case_ "crack covering all of Sigma" "covers all of Sigma" \
  '/Physical Curve("Sigma")/d; s/Physical Curve("crack") = {12, 14};/Physical Curve("crack") = {11, 12, 13, 14, 15};/' \
  --set "Geometry/Clamped sides=bottom, top" \
  --set "Loads/Layer 1/Traction on bottom=0; 0" --set "Loads/Layer 1/Traction on top=0; 0"
sed "$edge_crack" "$source_dir/two_cracks.geo" > edge_crack.geo
sed 's/two_cracks.geo/edge_crack.geo/; s/Clamped sides = left, right/Clamped sides = right/' \
  "$source_dir/two_cracks.prm" > edge_crack.prm
why=""
got=$(energy edge_crack.prm)
[[ -n $got ]] || why="run failed: $(cat run_stderr)"
[[ -z $(ls tmp) ]] || why="$why; temporary directory left: $(ls tmp)"
report "edge crack with its mouth on a free part accepted" "$why"
case_ "free specimen, unbalanced loads" "a free specimen's loads must be in equilibrium" 's/^$//' \
  --set "Geometry/Clamped sides=" --set "Loads/Layer 1/Traction on top=0; 1"
case_ "boundary curve in Sigma" "an interface must separate the two regions it joins" \
  's/Physical Curve("Sigma") = {11, 13, 15};/Physical Curve("Sigma") = {11, 13, 15, 2};/; s/Physical Curve("right") = {2, 3};/Physical Curve("right") = {3};/'
case_ "interface edges in no group" "'Omega-' and 'Omega+' share the edge at (-0.4375, 0), which is in no interface's curves" \
  's/Physical Curve("Sigma") = {11, 13, 15};/Physical Curve("Sigma") = {11, 15};/'
case_ "geometry gmsh cannot mesh" "Unknown control point 99" 's/^Line(4) = {3, 4};/Line(4) = {3, 99};/'
case_ "missing file" "no such file" 's/^$//' --set "Geometry/Gmsh file=missing.geo"
# --- Regions and interfaces beyond Omega-, Omega+ and Sigma (ply_drop.geo:
# 'Region 3' above Omega+, interface 2 'Sigma 2'/'crack 2' between them).
case3_ "regions numbered with a gap" "the physical surface 'Region 4' has no region 'Region 3' below it" \
  's/Physical Surface("Region 3")/Physical Surface("Region 4")/'
case3_ "a region named Region 1" "the physical surface 'Region 1' names a region that is called 'Omega-'" \
  's/Physical Surface("Omega-")/Physical Surface("Region 1")/'
case3_ "interfaces numbered with a gap" "no physical curve named 'Sigma 2' or 'crack 2' (the interfaces are 'Sigma', 'Sigma 2', 'Sigma 3', ... without gaps)" \
  's/Physical Curve("Sigma 2")/Physical Curve("Sigma 3")/; s/Physical Curve("crack 2")/Physical Curve("crack 3")/'
case3_ "an interface between two pairs of regions" "the 'crack 2' edge at (20.5, 2) separates 'Omega+' and 'Region 3', other edges of interface 2 'Omega-' and 'Omega+': an interface joins two regions" \
  's/Physical Curve("Sigma") = {10};/Physical Curve("Sigma") = {12};/; s/Physical Curve("Sigma 2") = {12};/Physical Curve("Sigma 2") = {10};/'
case3_ "Sigma between the wrong regions" "Sigma separates 'Omega+' and 'Region 3'; Sigma is the interface between 'Omega-' and 'Omega+'" \
  's/Physical Curve("Sigma") = {10};/Physical Curve("Sigma") = {11, 12};/; s/Physical Curve("Sigma 2") = {12};/Physical Curve("Sigma 2") = {10};/; /Physical Curve("crack 2")/d'
# --- Ply groups (physical surfaces inside the regions).
case_ "ply group not in the file" "Materials/Layer k/Ply groups names 'upper', which is not a physical surface of Geometry/Gmsh file 'scene.geo'" \
  's/^$//' --set "Materials/Layer 1/Ply groups=upper"
case_ "cell in two ply groups" "is in two ply groups, 'a' and 'b' (Materials/Layer k/Ply groups): a cell lies in one ply" \
  '$a Physical Surface("a") = {2}; Physical Surface("b") = {2};' \
  --set "Materials/Layer 1/Ply groups=a" --set "Materials/Layer 2/Ply groups=b"
# A ply group of the layer's own law, and a named surface inside Omega+ that
# no entry names (a note): the energy of two_cracks.prm.
sed '$a Physical Surface("upper") = {2};' "$source_dir/two_cracks.geo" > scene.geo
sed 's/two_cracks.geo/scene.geo/' "$source_dir/two_cracks.prm" > scene.prm
accept "ply group of the layer's own law" --set "Materials/Layer 1/Ply groups=upper"
accept "named surface inside a region, no ply group"
grep -qF "note: the physical surface 'upper' of Geometry/Gmsh file is not among Materials/Layer k/Ply groups" run_stdout
report "named surface inside a region: a note names it" "$([[ $? -eq 0 ]] || echo 'no note')"
printf '$MeshFormat\n4.1 0 8\n$EndMeshFormat\n' > other.msh
case_ "mesh of format 4" "format 2" 's/^$//' --set "Geometry/Gmsh file=other.msh"

# --- Scene files that run programs or write files: refused before gmsh
# runs, naming file:line; the command did not run.
# not_run NAME EXPECTED-FRAGMENT FILE GEO-SED-SCRIPT: refused, FILE absent.
not_run() {
  local name=$1 expect=$2 file=$3 edit=$4
  rm -f "$file"
  case_ "$name" "$expect" "$edit"
  if [[ -e $file ]]; then
    echo "$name: no ($file was written)"
    failures=$((failures + 1))
  fi
}
not_run "SystemCall" "scene.geo:75: 'SystemCall \"touch $work/ran\"' runs a shell command" \
  "$work/ran" "\$a SystemCall \"touch $work/ran\";"
not_run "NonBlockingSystemCall" "'NonBlockingSystemCall" "$work/ran" \
  "\$a NonBlockingSystemCall \"touch $work/ran\";"
not_run "Printf > file" "'Printf(\"x\") > \"$work/written\"' writes a file" \
  "$work/written" "\$a Printf(\"x\") > \"$work/written\";"
not_run "Printf >> file" "writes a file" "$work/written" \
  "\$a Printf(\"x %g\", 1) >> \"$work/written\";"
not_run "Save" "'Save \"$work/written\"' writes a file" "$work/written" \
  "\$a Mesh 2; Save \"$work/written\";"
not_run "Print" "writes a picture file" "$work/written.png" \
  "\$a Print \"$work/written.png\";"
not_run "ExternalProcess field" "runs an external program (a mesh size field)" \
  "$work/ran" "\$a Field[1] = ExternalProcess; Field[1].CommandLine = \"touch $work/ran\"; Background Field = 1;"
not_run "CreateDir" "creates a directory" "$work/made" "\$a CreateDir \"$work/made\";"
not_run "Plugin Run" "runs a plugin" "$work/written" \
  "\$a Plugin(NewView).Run;"
not_run "General.SaveOptions" "General.SaveOptions" "$work/written" \
  "\$a General.SaveOptions = 1;"
not_run "General.OptionsFileName" "General.OptionsFileName" "$work/written" \
  "\$a General.OptionsFileName = \"$work/written\";"
not_run "Solver options" "Solver options start external solver programs" \
  "$work/written" "\$a Solver.Executable0 = \"/bin/touch\";"
not_run "Merge of a CAD file" "loads another file" "$work/written" \
  "\$a Merge \"part.step\";"
not_run "ShapeFromFile" "loads a CAD file" "$work/written" \
  "\$a v() = ShapeFromFile(\"part.brep\");"
not_run "computed Include path" "has a computed path" "$work/written" \
  "\$a Include StrCat(\"more\", \".geo\");"
not_run "string variable as Include path" "has a computed path" "$work/written" \
  "\$a name = \"more.geo\"; Include name;"
printf '// included\nSystemCall "touch %s/ran";\n' "$work" > nested.geo
printf 'Include "nested.geo";\n' > inner.geo
not_run "SystemCall in an Include of an Include" \
  "nested.geo:2: 'SystemCall \"touch $work/ran\"' runs a shell command" \
  "$work/ran" '$a Include "inner.geo";'
not_run "SystemCall in a Merge'd .geo" "nested.geo:2:" "$work/ran" \
  '$a Merge "nested.geo";'
# The same words in comments and strings are no statements.
sed -e '$a // SystemCall "touch ran";' \
    -e '$a /* Printf("x") > "written"; Save "m.msh";' -e '$a SystemCall "y"; */' \
    -e '$a Printf("SystemCall \\"); Printf("Save x.msh; // /*");' \
    "$source_dir/two_cracks.geo" > scene.geo
sed 's/two_cracks.geo/scene.geo/' "$source_dir/two_cracks.prm" > scene.prm
accept "commands in comments and strings"
# With --allow-gmsh-commands they run (once for the groups, once for the
# mesh) and the scene is the same.
rm -f ran written
sed -e "\$a SystemCall \"touch $work/ran\";" -e "\$a Printf(\"x\") > \"$work/written\";" \
  "$source_dir/two_cracks.geo" > scene.geo
accept "--allow-gmsh-commands" --allow-gmsh-commands
[[ -e ran && -e written ]] || { echo "--allow-gmsh-commands: no (the commands did not run)"; failures=$((failures + 1)); }
# Options that break reading are overridden: the same mesh and energy.
sed -e '$a Mesh.Binary = 1;' -e '$a Mesh.MshFileVersion = 4.1;' \
    -e '$a Mesh.ElementOrder = 2;' -e '$a Mesh.SaveAll = 1;' \
    "$source_dir/two_cracks.geo" > scene.geo
accept "Mesh.Binary, Mesh.MshFileVersion, Mesh.ElementOrder overridden"
sed -e '$a Mesh 2;' -e '$a SetOrder 2;' "$source_dir/two_cracks.geo" > scene.geo
accept "a second-order mesh made by the scene"

# --- Group names as gmsh reports them.
case_ "group declared in a comment" "Traction on hole" \
  '$a // Physical Curve("hole") = {1};' --set "Loads/Layer 1/Traction on hole=0; 1"
# "top" from an Include'd file and "bottom" built with StrCat: the same
# energy as two_cracks.prm.
sed -e '/Physical Curve("top")/d' \
    -e 's/Physical Curve("bottom")/Physical Curve(StrCat("bot", "tom"))/' \
    -e '$a Include "groups/top.geo";' "$source_dir/two_cracks.geo" > scene.geo
mkdir -p groups
printf '// The top side.\nPhysical Curve("top") = {4};\n' > groups/top.geo
accept "names from an Include and from StrCat"
case_ "name with =" "the physical curve name 'a=b' cannot name a boundary part" \
  's/Physical Curve("top")/Physical Curve("a=b")/' \
  --set "Loads/Layer 1/Traction on top=0; 0"

# --- Cells and edges outside the groups bilayer understands.
square='$a Point(21) = {3, -0.5, 0, 0.25}; Point(22) = {4, -0.5, 0, 0.25}; Point(23) = {4, 0, 0, 0.25}; Point(24) = {3, 0, 0, 0.25}; Line(21) = {21, 22}; Line(22) = {22, 23}; Line(23) = {23, 24}; Line(24) = {24, 21}; Curve Loop(21) = {21, 22, 23, 24}; Plane Surface(21) = {21}; Recombine Surface{21};'
case_ "surface in no physical group" "the cells of Gmsh surface 21 (e.g. at" "$square"
case_ "surface in an unknown group" "are in the physical surface 'glue'" \
  "$square"$'\n''$a Physical Surface("glue") = {21};'
case_ "surface in Omega- and Omega+" "is in two physical surfaces, 'Omega-' and 'Omega+'" \
  's/Physical Surface("Omega-") = {1};/Physical Surface("Omega-") = {1, 2};/'
case_ "curve in Sigma and crack" "is in two physical curves, 'Sigma' and 'crack'" \
  's/Physical Curve("crack") = {12, 14};/Physical Curve("crack") = {12, 14, 13};/'
case_ "curve in two boundary parts" "is in two physical curves, 'top' and 'lid'" \
  '$a Physical Curve("lid") = {4};'
case_ "unnamed physical curve" "in the physical curve number 40 (without a name)" \
  '$a Physical Curve(40) = {1};'
# .msh files made from two_cracks.geo and edited.
gmsh -2 -format msh2 two_cracks.geo -o plain.msh > /dev/null 2>&1
# msh_case NAME EXPECTED-FRAGMENT PYTHON-EDIT: plain.msh edited by a
# function edit(sections) of the section lines.
msh_case() {
  python3 - "$3" > scene.msh <<'EOF'
import sys
text = open("plain.msh").read().split("\n")
sections, current = {}, None
for line in text:
    if line.startswith("$End"):
        current = None
    elif line.startswith("$"):
        current = line[1:]
        sections[current] = []
    elif current is not None:
        sections[current].append(line)
exec(sys.argv[1])
for name, lines in sections.items():
    print("$" + name)
    print("\n".join(lines))
    print("$End" + name)
EOF
  sed 's/two_cracks.geo/scene.msh/' "$source_dir/two_cracks.prm" > scene.prm
  [[ -z $1 ]] || refuse "$1" "$2"
}
quad='next(i for i, l in enumerate(e) if len(l.split()) > 2 and l.split()[1] == "3")'
msh_case "cell of physical tag 0 in a .msh" "are in no physical surface" \
  "e = sections['Elements']; i = $quad; v = e[i].split(); v[3] = '0'; e[i] = ' '.join(v)"
msh_case "two physical surfaces named Omega- in a .msh" \
  "two physical surfaces (tags 1 and 9) are named 'Omega-'" \
  "p = sections['PhysicalNames']; p.append('2 9 \"Omega-\"'); p[0] = str(len(p) - 1)"
msh_case "crack edge in a second group named crack" \
  "two physical curves (tags 4 and 9) are named 'crack'" \
  "p = sections['PhysicalNames']; p.append('1 9 \"crack\"'); p[0] = str(len(p) - 1); e = sections['Elements']; i = next(i for i, l in enumerate(e) if len(l.split()) > 3 and l.split()[1:4] == ['1', '2', '4']); v = e[i].split(); v[3] = '9'; e[i] = ' '.join(v)"
msh_case "boundary part inside the mesh" "is an edge of 2 cells, not of the outer boundary" \
  "e = sections['Elements']; c = [l.split() for l in e[1:] if l.split()[1] == '3']; n = {l.split()[0]: l.split()[1:3] for l in sections['Nodes'][1:]}; q = next(v for v in c if all(abs(float(n[k][1])) not in (0.0, 0.5) and abs(float(n[k][0])) != 2 for k in v[5:9])); e.append('99999 1 2 6 4 ' + q[5] + ' ' + q[6]); e[0] = str(len(e) - 1)"
msh_case "node off the plane" "node 5 lies off the plane z = 0 (z = 0.3)" \
  "d = sections['Nodes']; v = d[5].split(); v[3] = '0.3'; d[5] = ' '.join(v)"
msh_case "corrupt tag count" "claims 99999999 tags (the file is corrupt" \
  "e = sections['Elements']; v = e[3].split(); v[2] = '99999999'; e[3] = ' '.join(v)"
msh_case ".msh without \$PhysicalNames" "no named physical groups (no \$PhysicalNames section)" \
  "del sections['PhysicalNames']"
# A cell given the other way round (the mesh of mixed orientation) is the
# same cell: the energy of plain.msh.
msh_case "" "" \
  "e = sections['Elements']; i = $quad; v = e[i].split(); v[5:9] = v[5:9][::-1]; e[i] = ' '.join(v)"
got=$(energy scene.prm)
sed 's/two_cracks.geo/plain.msh/' two_cracks.prm > plain.prm
expected=$(energy plain.prm)
# (the same up to round-off: the cell's quadrature points come in another
# order)
python3 -c "import sys; a, b = float(sys.argv[1]), float(sys.argv[2]); sys.exit(abs(a - b) > 1e-9 * abs(b))" \
  "${got#*: }" "${expected#*: }" 2> /dev/null && why="" || why="$got, plain.msh: $expected"
report "one inverted cell" "$why"

# --- gmsh that runs too long, or ends without a mesh.
case_ "scene that loops forever" "gmsh was stopped after 2 s (Mesh/Gmsh time limit)" \
  '$a For i In {1 : 1e12}\nx = i;\nEndFor' --set "Mesh/Gmsh time limit=2"
mkdir -p fakebin
printf '#!/bin/sh\necho $$ > "%s/gmsh.pid"\nexec sleep 100\n' "$work" > fakebin/gmsh
chmod +x fakebin/gmsh
cp two_cracks.prm scene.prm
rm -f gmsh.pid
run_path=$work/fakebin:$PATH refuse "gmsh that hangs" "gmsh was stopped after 1 s" \
  --set "Mesh/Gmsh time limit=1"
if [[ ! -s gmsh.pid ]] || still_running "$(cat gmsh.pid)"; then
  echo "gmsh that hangs: no (gmsh still runs)"; failures=$((failures + 1))
fi
# stopped SIGNAL: bilayer stopped by SIGNAL while gmsh hangs.
stopped() {
  local signal=$1 why=""
  rm -f gmsh.pid
  PATH=$work/fakebin:$PATH "$bilayer" scene.prm > stdout 2> stderr &
  local run=$!
  for _ in $(seq 100); do [[ -s gmsh.pid ]] && break; sleep 0.05; done
  kill -"$signal" "$run"
  { wait "$run"; } 2> /dev/null
  local rc=$?
  [[ $rc -eq $((128 + $(kill -l "$signal"))) ]] || why="exit status $rc"
  [[ -s gmsh.pid ]] || why="$why; gmsh did not start"
  ! still_running "$(cat gmsh.pid)" || why="$why; gmsh still runs"
  [[ $signal == KILL || -z $(ls tmp) ]] || why="$why; temporary directory left"
  report "bilayer stopped by SIG$signal while gmsh runs" "$why"
  rm -rf tmp/*
}
stopped TERM
stopped HUP
stopped KILL
printf '#!/bin/sh\nexit 0\n' > fakebin/gmsh
run_path=$work/fakebin:$PATH refuse "gmsh exits 0 without a mesh" \
  "gmsh ended without error but wrote no mesh"
case_ "scene that exits early" "wrote no mesh" '/^Physical Surface("Omega-")/i Exit;'
printf '#!/bin/sh\nsleep 11\nexit 0\n' > fakebin/gmsh
cp two_cracks.prm scene.prm
run_path=$work/fakebin:$PATH refuse "gmsh that runs long" "wrote no mesh"
grep -qF "bilayer: gmsh is still reading the groups of" stdout ||
  { echo "gmsh that runs long: no (no progress line)"; failures=$((failures + 1)); }
mkdir -p emptybin
run_path=$work/emptybin refuse "gmsh missing" "the gmsh command is missing"

# --- bilayer --check-geometry: the checks of a run, on quadrilaterals and
# on triangles.
cp "$source_dir/two_cracks.geo" quadrilaterals.geo
sed -e '/^Recombine Surface/d' "$source_dir/two_cracks.geo" > triangles.geo
for kind in quadrilaterals triangles; do
  why=""
  "$bilayer" --check-geometry $kind.geo > check_stdout 2> stderr || why="exit status $?"
  [[ $(tail -1 check_stdout) == PASS ]] || why="$why; no PASS"
  grep -q "^cells: Omega- [0-9]* $kind, Omega+ [0-9]* $kind\$" check_stdout || why="$why; no $kind"
  grep -q '^  2 [0-9]* "Omega-": [0-9]' check_stdout || why="$why; no group Omega-"
  [[ $(grep -c '^  piece (' check_stdout) -eq 2 ]] || why="$why; not two crack pieces"
  report "--check-geometry on $kind" "$why"
done
# The edge crack: PASS, its mouth and the part there named (a run must leave
# it free), its one tip; the other piece keeps its line.
why=""
"$bilayer" --check-geometry edge_crack.geo > check_stdout 2> stderr || why="exit status $?"
[[ $(tail -1 check_stdout) == PASS ]] || why="$why; no PASS"
grep -qF "  piece (-2, 0) -- (-0.5, 0): length 1.5; edge crack: its mouth (-2, 0) lies on the boundary part(s) 'left' (no tip there; a run must not clamp them), its tip (-0.5, 0)" check_stdout ||
  why="$why; mouth not named"
grep -qxF "  piece (0.5, 0) -- (1.5, 0): length 1" check_stdout || why="$why; inner piece"
report "--check-geometry on an edge crack" "$why"
# Three regions (ply_drop.geo: 60, 60 and 40 cells of size 1 by its
# transfinite curves): every region and interface 2 with its edge crack
# from the end of the dropped ply (20, 2) to the tip (35, 2).
why=""
"$bilayer" --check-geometry "$source_dir/ply_drop.geo" > check_stdout 2> stderr || why="exit status $?"
[[ $(tail -1 check_stdout) == PASS ]] || why="$why; no PASS"
grep -qxF "cells: Omega- 60 quadrilaterals, Omega+ 60 quadrilaterals, Region 3 40 quadrilaterals" check_stdout ||
  why="$why; not the three regions"
grep -qF "interface 2 ('Sigma 2', between 'Omega+' and 'Region 3') (with the crack): 2 pieces, length 40, from (20, 2) to (60, 2)" check_stdout ||
  why="$why; no interface 2"
grep -qF "  piece (20, 2) -- (35, 2): length 15; edge crack: its mouth (20, 2)" check_stdout ||
  why="$why; not the crack of interface 2"
report "--check-geometry on three regions" "$why"
sed -e '/Physical Surface("Omega+")/d' "$source_dir/two_cracks.geo" > no_plus.geo
why=""
"$bilayer" --check-geometry no_plus.geo > check_stdout 2> stderr
rc=$?
[[ $rc -eq 1 ]] || why="exit status $rc"
[[ ! -s check_stdout && $(wc -l < stderr) -eq 1 ]] || why="$why; not one line"
grep -qF "bilayer: error: Geometry/Gmsh file 'no_plus.geo': no physical surface named 'Omega+'" stderr ||
  why="$why; Omega+ not named"
report "--check-geometry on a scene without Omega+" "$why"

# --- scripts/check_geo (bilayer --check-geometry) on a hostile scene.
export BILAYER=$bilayer
sed -e "\$a SystemCall \"touch $work/ran\";" "$source_dir/two_cracks.geo" > hostile.geo
rm -f ran
why=""
python3 "$check_geo" hostile.geo > check_stdout 2>&1 && why="exit status 0"
grep -qF "hostile.geo:75: 'SystemCall" check_stdout || why="$why; statement not named"
[[ ! -e ran ]] || why="$why; the command ran"
report "check_geo on a hostile scene" "$why"
why=""
python3 "$check_geo" --allow-gmsh-commands hostile.geo > check_stdout 2>&1 || why="exit status $?"
[[ -e ran ]] || why="$why; the command did not run"
report "check_geo --allow-gmsh-commands" "$why"
exit $((failures > 0))
