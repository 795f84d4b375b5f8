#!/usr/bin/env bash
# The bad-input catalogue: every case must end with exactly one line
# "bilayer: error: ..." on stderr that names the parameter (and, where
# deal.II gives them, the file and line) with the allowed range, a non-zero
# exit, no backtrace, no file outside the output directory changed, a
# pre-existing output directory left unchanged and no staging directory
# behind. Several members of each class of hostile input are tried: output
# directories that hold the user's files (the working directory under other
# names, its ancestors, a directory holding an input, foreign files,
# symbolic links), concurrent runs into one directory, parameter files that
# are no regular file or include themselves, names and sizes of text that
# broke the expression parser, scenes too large for the memory, numbers
# outside the range of double, friction entries (a Tresca bound negative or
# not finite on the crack, also under mpirun), and command-line mistakes.
# Then the runs
# that do not refuse: a failed run keeps the directory and puts its results
# in DIR.failed, a failed write keeps it too, a passing run replaces it and
# removes DIR.failed.
# Usage: bad_input_catalogue.sh BILAYER PARAMETER_FILE
set -u
bilayer=$(realpath "$1")
prm_source=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
cp "$prm_source" scene.prm
prm=scene.prm
failures=0
fail() {
  echo "$1: no ($2)"
  [[ -f stderr ]] && cat stderr
  failures=$((failures + 1))
}

# The output directory of an earlier run (bilayer's own), with a file the
# user added; every refusal must leave it and all other files unchanged.
"$bilayer" "$prm" --set "Output/Output directory=out" --set "Output/Write VTU=false" \
  > /dev/null 2>&1 || fail "set-up run" "exit status $?"
echo 'kept' > out/notes.txt
mkdir -p keep/sub
echo 'precious' > keep/data.txt
echo 'precious' > keep/sub/data.txt
# (The files of the check itself and a failed run's out.failed aside.)
snapshot() {
  find . \( -path ./stdout -o -path ./stderr -o -path ./out.failed \) -prune -o -type f -print0 \
    | sort -z | xargs -0 md5sum
}
before=$(snapshot)

# check NAME EXPECTED-FRAGMENT ARGS...: one refusal. With
# CATALOGUE_STRIDE=K (scripts/sanitize) every K-th refusal alone, the first
# included: their code paths are alike and a run under the sanitizers costs
# seconds.
catalogue_case=0
check() {
  local name=$1 expect=$2
  shift 2
  catalogue_case=$((catalogue_case + 1))
  if (( ${CATALOGUE_STRIDE:-1} > 1 && (catalogue_case - 1) % CATALOGUE_STRIDE != 0 )); then
    return 0
  fi
  "$bilayer" "$@" > stdout 2> stderr
  local rc=$? why=""
  [[ $rc -eq 1 ]] || why="exit status $rc"
  [[ $(wc -l < stderr) -eq 1 ]] || why="$why; $(wc -l < stderr) lines on stderr"
  grep -qF "bilayer: error: " stderr || why="$why; no 'bilayer: error:'"
  grep -qF -- "$expect" stderr || why="$why; '$expect' not named"
  ! grep -qiE "stacktrace|terminate called|^-{5,}" stderr || why="$why; backtrace"
  [[ "$(snapshot)" == "$before" ]] || why="$why; files changed"
  [[ -z $(find . \( -name '*.partial' -o -name '*.lock' \) ! -path ./empty.lock) ]] || why="$why; staging or lock left behind"
  if [[ -z $why ]]; then echo "$name: yes"; else fail "$name" "$why"; fi
}
run() {
  local name=$1 expect=$2
  shift 2
  check "$name" "$expect" "$prm" --set "Output/Output directory=fresh/out" --set "$@"
  [[ ! -e fresh ]] || fail "$name" "'fresh' left behind"
}

# Parameter files.
printf 'subsection Mesh\n  sett Cells along Sigma = 8\nend\n' > malformed.prm
printf 'subsection Mesh\n  set Cels along Sigma = 8\nend\n' > unknown_entry.prm
printf 'subsection Meshes\n  set Cells along Sigma = 8\nend\n' > unknown_subsection.prm
printf 'subsection Mesh\n  set Cells along Sigma = 8\n' > unterminated.prm
printf 'subsection Solver\n  set Method = Active-Set\nend\n' > misspelled_value.prm
printf 'subsection Contact\n  set Cohesive strength = 0.3\nend\n' > cohesive.prm
printf 'subsection Materials\n subsection Layer 1\n  set Ply heights = 0.5\n  subsection Ply 3\n   set E_1 = 2\n  end\n end\nend\n' > ply3.prm
printf 'subsection Materials\n subsection Layer 3\n  set Poisson'"'"'s ratio = 0.3\n end\nend\n' > layer3.prm
printf 'include self.prm\n' > self.prm
printf 'include b.prm\n' > a.prm
printf 'include a.prm\n' > b.prm
printf 'include nothere.prm\n' > include_missing.prm
mkdir -p a_directory.prm mesh_dir_minus mesh_dir_plus
mkfifo a_fifo.prm
before=$(snapshot)
check "malformed line" "Line <2> of file <malformed.prm>" malformed.prm
check "unknown entry" "Line <2> of file <unknown_entry.prm>: No entry with name <Cels along Sigma>" unknown_entry.prm
check "unknown subsection" "Line <1> of file <unknown_subsection.prm>: There is no such subsection to be entered: Meshes; did you mean 'Mesh'?" unknown_subsection.prm
check "unterminated subsection" "unterminated.prm" unterminated.prm
check "misspelled choice" "Line <2> of file <misspelled_value.prm>: The entry value Active-Set for the entry named Method does not match the given pattern: [Selection uzawa|accelerated|active set ]; did you mean 'active set'?" misspelled_value.prm
check "misspelled choice in --set" "--set Solver/Method=uzawaa: The string <uzawaa> does not match the given pattern <[Selection uzawa|accelerated|active set ]>; did you mean 'uzawa'?" "$prm" --set "Solver/Method=uzawaa"
# Entries about physics bilayer does not model are no misspellings: the
# README's table of what it models, not the nearest entry.
check "entry of physics not modelled" "--set Fracture/Critical energy release rate=1: no entry 'Fracture/Critical energy release rate' is declared; what bilayer models and what not: the README's table" "$prm" --set "Fracture/Critical energy release rate=1"
check "entry of physics not modelled in a file" "No entry with name <Cohesive strength> was declared in the current subsection; what bilayer models and what not" cohesive.prm
# Physics that bilayer models (friction) has entries: a name near one of
# them is a misspelling.
check "ply height outside Omega" "Materials/Layer 1/Ply heights must lie strictly inside Omega, -1 < y < 1, got 2" "$prm" --set "Materials/Layer 1/Ply heights=0.5, 2"
check "ply heights not increasing" "Materials/Layer 1/Ply heights must be a list of heights y that increase strictly (the ply boundaries from the bottom), got '0.5, 0.2'" "$prm" --set "Materials/Layer 1/Ply heights=0.5, 0.2"
check "ply beyond the layer's" "Line <4> of file <ply3.prm>: There is no such subsection to be entered: Materials.Layer 1.Ply 3; a layer with n Materials/Layer k/Ply heights or n Ply groups has the subsections Ply 1 ... Ply n+1" ply3.prm
check "ply groups in the rectangle scene" "Materials/Layer 1/Ply groups names physical surfaces of a Gmsh scene; without Geometry/Gmsh file (or with Mesh/Mesh files) it must be empty" "$prm" --set "Materials/Layer 1/Ply groups=upper"
check "ply heights and ply groups" "Materials/Layer 1/Ply heights and Materials/Layer 1/Ply groups: give one of them" "$prm" --set "Materials/Layer 1/Ply heights=0.5" --set "Materials/Layer 1/Ply groups=upper"
check "ply group named twice" "Materials/Layer 1/Ply groups must be a list of the names of Gmsh physical surfaces inside the regions, each once (not the regions 'Omega-', 'Omega+', 'Region K' themselves), got 'upper, upper'" "$prm" --set "Materials/Layer 1/Ply groups=upper, upper"
check "a region as a ply group" "Materials/Layer 2/Ply groups must be a list of the names of Gmsh physical surfaces" "$prm" --set "Materials/Layer 2/Ply groups=Omega+"
check "layer beyond the stack" "Line <2> of file <layer3.prm>: There is no such subsection to be entered: Materials.Layer 3; Materials/Number of layers = N gives the subsections Layer 1 ... Layer max(2, N) of Materials and Loads" layer3.prm
check "too many layers" "Materials/Number of layers=65: The string <65> does not match the given pattern <[Integer range 1...64 (inclusive)]>" "$prm" --set "Materials/Number of layers=65"
check "misspelled friction entry" "no entry 'Contact/Friction coeficient' is declared; did you mean 'Contact/Friction coefficient'?" "$prm" --set "Contact/Friction coeficient=0.3"
check "plausible misspelling in --set" "no entry 'Mesh/Polynomial degree layer 1' is declared; did you mean 'Mesh/Polynomial degree of layer 1'?" "$prm" --set "Mesh/Polynomial degree layer 1=2"
check "choice far from every allowed one" "pattern <[Selection uzawa|accelerated|active set ]>" "$prm" --set "Solver/Method=newton"
check "missing parameter file" "cannot open parameter file 'no-such-file.prm': no such file" no-such-file.prm
check "parameter file is a directory" "parameter file 'a_directory.prm': it is a directory" a_directory.prm
check "parameter file is a device" "parameter file '/dev/null': it is not a regular file" /dev/null
check "parameter file is a FIFO" "parameter file 'a_fifo.prm': it is not a regular file" a_fifo.prm
check "file includes itself" "includes itself" self.prm
check "files include each other" "includes itself" a.prm
check "included file missing" "cannot open file 'nothere.prm' included from 'include_missing.prm'" include_missing.prm

# The command line.
check "no arguments" "no parameter file given"
check "two parameter files" "more than one parameter file given" "$prm" "$prm"
check "--set without a value" "--set needs a value" "$prm" --set
check "unknown option" "unknown option '--frobnicate'" "$prm" --frobnicate
check "--print-parameters --set without a file" "--print-parameters with --set needs the parameter file" --print-parameters --set "Mesh/Cells along Sigma=8"
check "--version with a file" "--version takes no parameter file or --set" --version "$prm"
check "--check-geometry without a file" "--check-geometry needs the geometry file" --check-geometry
check "--check-geometry with a parameter file" "takes no parameter file, got '$prm'" --check-geometry nothere.geo "$prm"
check "--check-geometry of a missing file" "Geometry/Gmsh file 'nothere.geo'" --check-geometry nothere.geo
check "--check-geometry --set outside Mesh" "--set Solver/Method=uzawa: no entry 'Solver/Method' is declared" --check-geometry nothere.geo --set "Solver/Method=uzawa"
check "--set without '='" "--set expects 'Section/Entry=value'" "$prm" --set "Mesh/Cells along Sigma"
check "--set of an unknown entry" "--set Mesh/Cels along Sigma=8" "$prm" --set "Mesh/Cels along Sigma=8"

# Entries and their ranges.
run "value outside its pattern" "Mesh/Cells along Sigma=-3: The string <-3> does not match the given pattern <[Integer range 1...100000" "Mesh/Cells along Sigma=-3"
run "zero cells" "Mesh/Cells along Sigma=0: The string <0> does not match the given pattern <[Integer range 1...100000" "Mesh/Cells along Sigma=0"
run "degree 0" "Mesh/Polynomial degree of layer 1=0: The string <0> does not match the given pattern <[Integer range 1...4" "Mesh/Polynomial degree of layer 1=0"
run "E <= 0" "Materials/Layer 2/Young's modulus must be > 0, got 0" "Materials/Layer 2/Young's modulus=0"
run "E < 0" "Materials/Layer 1/Young's modulus=-1: The string <-1> does not match the given pattern <[Double 0...MAX_DOUBLE" "Materials/Layer 1/Young's modulus=-1"
run "Poisson's ratio 0.5" "Materials/Layer 1/Poisson's ratio must lie in (-1, 0.5), got 0.5" "Materials/Layer 1/Poisson's ratio=0.5"
run "Poisson's ratio -1" "Materials/Layer 2/Poisson's ratio must lie in (-1, 0.5), got -1" "Materials/Layer 2/Poisson's ratio=-1"
run "Poisson's ratio 0.5 in plane strain" "Materials/Layer 2/Poisson's ratio must lie in (-1, 0.5), got 0.5" "Materials/Layer 2/Plane state=plane strain" --set "Materials/Layer 2/Poisson's ratio=0.5"
run "Poisson's ratio -1 in plane stress" "Materials/Layer 1/Poisson's ratio must lie in (-1, 0.5] (plane stress), got -1" "Materials/Layer 1/Plane state=plane stress" --set "Materials/Layer 1/Poisson's ratio=-1"
# Laws other than the isotropic one: constants outside their admissible
# range, a stiffness that is not positive definite, load expressions that
# name the constants of isotropic layers.
run "stiffness not positive definite" "Materials/Layer 1/Stiffness must be symmetric positive definite (C11 > 0, C11 C22 - C12^2 > 0 and det [[C11, C12, C16], [C12, C22, C26], [C16, C26, C66]] > 0), got '100, 120, 0, 100, 0, 30'" "Materials/Layer 1/Law=anisotropic" --set "Materials/Layer 1/Stiffness=100, 120, 0, 100, 0, 30"
run "stiffness with shear coupling not positive definite" "Materials/Layer 2/Stiffness must be symmetric positive definite" "Materials/Layer 2/Law=anisotropic" --set "Materials/Layer 2/Stiffness=100, 20, 60, 100, 0, 30"
run "stiffness of five numbers" "Materials/Layer 2/Stiffness=1, 2, 3, 4, 5: The string <1, 2, 3, 4, 5> does not match the given pattern" "Materials/Layer 2/Stiffness=1, 2, 3, 4, 5"
run "orthotropic shear modulus 0" "Materials/Layer 1/E_1, E_2, E_3 and G_12 must be > 0, got E_1, E_2, E_3, G_12 = 200, 200, 200, 0" "Materials/Layer 1/Law=orthotropic" --set "Materials/Layer 1/G_12=0"
run "orthotropic nu_12 beyond sqrt(E_1/E_2)" "Materials/Layer 2/nu_12 must satisfy |nu_12| < sqrt(E_1/E_2) = 0.5 (a positive definite compliance), got 0.6" "Materials/Layer 2/Law=orthotropic" --set "Materials/Layer 2/E_1=10" --set "Materials/Layer 2/E_2=40" --set "Materials/Layer 2/nu_12=0.6"
run "orthotropic nu_12 in plane stress" "Materials/Layer 1/nu_12 must satisfy |nu_12| < sqrt(E_1/E_2) = 1 (a positive definite compliance), got -1.2" "Materials/Layer 1/Law=orthotropic" --set "Materials/Layer 1/Plane state=plane stress" --set "Materials/Layer 1/nu_12=-1.2"
run "orthotropic compliance not positive definite" "Materials/Layer 1/nu_12, nu_13, nu_23 with E_1, E_2, E_3 must make the 3-D compliance positive definite: 1 - nu_12 nu_21 - nu_23 nu_32 - nu_13 nu_31 - 2 nu_21 nu_32 nu_13 > 0 (nu_ji = nu_ij E_j/E_i), got -0.512 for nu_12, nu_13, nu_23 = 0.6, 0.6, 0.6" "Materials/Layer 1/Law=orthotropic" --set "Materials/Layer 1/nu_12=0.6" --set "Materials/Layer 1/nu_13=0.6" --set "Materials/Layer 1/nu_23=0.6"
run "orientation angle beyond 360" "Materials/Layer 1/Orientation angle=400: The string <400> does not match the given pattern" "Materials/Layer 1/Orientation angle=400"
run "constant using mu1 of an orthotropic layer" "Loads/Constants: 'c = 1e-3*mu1' uses mu1, a constant of isotropic layers only (E1, nu1, mu1, lambda1), but Materials/Layer 1/Law = orthotropic: write its value as a number" "Materials/Layer 1/Law=orthotropic"
run "traction using E1 of an orthotropic layer" "Loads/Layer 1/Traction on top side: '0; -E1*1e-3*x' uses E1, a constant of isotropic layers only (E1, nu1, mu1, lambda1), but Materials/Layer 1/Law = orthotropic" "Materials/Layer 1/Law=orthotropic" --set "Loads/Constants=c = 0.078" --set "Loads/Layer 1/Traction on top side=0; -E1*1e-3*x"
run "prescribed displacement using nu2 of an anisotropic layer" "Loads/Layer 2/Prescribed displacement: '0; 1e-3*nu2' uses nu2, a constant of isotropic layers only (E2, nu2, mu2, lambda2), but Materials/Layer 2/Law = anisotropic" "Materials/Layer 2/Law=anisotropic" --set "Loads/Layer 2/Prescribed displacement=0; 1e-3*nu2"
run "lambda1 at nu = 0.5 in plane stress" "Loads/Constants: 'c = 1e-9*lambda1' uses lambda1, which is infinite for Materials/Layer 1/Poisson's ratio = 0.5 (plane stress)" "Materials/Layer 1/Plane state=plane stress" --set "Materials/Layer 1/Poisson's ratio=0.5" --set "Loads/Constants=c = 1e-9*lambda1"
run "constant named E1 of an orthotropic layer" "Loads/Constants: the name 'E1' is reserved" "Materials/Layer 1/Law=orthotropic" --set "Loads/Constants=E1 = 1"
# Materials per side of Sigma (Materials/Layer k/Omega- and Omega+): the
# plane state is the layer's, a side's constants are checked like the
# layer's, naming the side's entry, and the load constants of a layer whose
# sides differ are not defined.
run "plane state on a side" "the plane state is one per layer (Materials/Layer k/Plane state), the same on both sides of Sigma" "Materials/Layer 1/Omega+/Plane state=plane stress"
run "negative Young's modulus on Omega+" "Materials/Layer 1/Omega+/Young's modulus: '-5' does not match the pattern [Double 0...MAX_DOUBLE (inclusive)] of Materials/Layer 1/Young's modulus (empty: as the layer)" "Materials/Layer 1/Omega+/Young's modulus=-5"
run "zero Young's modulus on Omega-" "Materials/Layer 2/Omega-/Young's modulus must be > 0, got 0" "Materials/Layer 2/Omega-/Young's modulus=0"
run "side stiffness not positive definite" "Materials/Layer 1/Omega-/Stiffness must be symmetric positive definite" "Materials/Layer 1/Omega-/Law=anisotropic" --set "Materials/Layer 1/Omega-/Stiffness=100, 120, 0, 100, 0, 30"
run "side orthotropic compliance not positive definite" "Materials/Layer 2/Omega+/nu_12, nu_13, nu_23 with E_1, E_2, E_3 must make the 3-D compliance positive definite" "Materials/Layer 2/Omega+/Law=orthotropic" --set "Materials/Layer 2/Omega+/nu_12=0.6" --set "Materials/Layer 2/Omega+/nu_13=0.6" --set "Materials/Layer 2/Omega+/nu_23=0.6"
run "mu1 of a layer whose sides differ" "Loads/Constants: 'c = 1e-3*mu1' uses mu1, which differs between the sides of the layer (mu = 78.125 on Materials/Layer 1/Omega-, 39.0625 on Omega+): write the value of one side as a number" "Materials/Layer 1/Omega+/Young's modulus=100"
run "E2 of a layer with an orthotropic side" "Loads/Layer 2/Prescribed displacement: '0; 1e-6*E2' uses E2, a constant of isotropic layers only (E2, nu2, mu2, lambda2), but Materials/Layer 2/Omega-/Law = orthotropic" "Materials/Layer 2/Omega-/Law=orthotropic" --set "Loads/Layer 2/Prescribed displacement=0; 1e-6*E2"
run "crack outside Sigma" "Geometry/Crack interval on Sigma must satisfy -1 <= x_start <= x_end <= 1, got '-2, 0.5'" "Geometry/Crack interval on Sigma=-2, 0.5"
# An edge crack needs a free or loaded side at its mouth (gamma_c and Gamma_D
# are disjoint), and some of Sigma must stay glued.
run "crack touching Gamma_D" "Geometry/Crack interval on Sigma = '-0.5, 1' reaches the right side (x = 1), which is clamped (Geometry/Clamped sides = 'left, right')" "Geometry/Crack interval on Sigma=-0.5, 1"
run "edge crack at a clamped side" "Geometry/Crack interval on Sigma = '-1, 0.5' reaches the left side (x = -1), which is clamped" "Geometry/Crack interval on Sigma=-1, 0.5" --set "Geometry/Clamped sides=left"
run "crack covering all of Sigma" "Geometry/Crack interval on Sigma = '-1, 1' covers all of Sigma" "Geometry/Crack interval on Sigma=-1, 1" --set "Geometry/Clamped sides=bottom, top" --set "Loads/Layer 1/Traction on bottom side=0; 0" --set "Loads/Layer 1/Traction on top side=0; 0"
run "free specimen, unbalanced loads" "nothing is clamped (Geometry/Clamped sides is empty): a free specimen's loads must be in equilibrium, but their resultant force is" "Geometry/Clamped sides=" --set "Loads/Layer 1/Traction on top side=0; 1"
# Several interfaces (Geometry/Interfaces above Sigma): the list's form, the
# heights in order inside Omega, each crack as on Sigma, one layer, no growth.
run "interfaces above Sigma malformed" "Geometry/Interfaces above Sigma must be a list of 'y' or 'y: x_start, x_end' separated by ';', got '0.5: 1'" "Geometry/Interfaces above Sigma=0.5: 1"
run "interfaces above Sigma out of order" "Geometry/Interfaces above Sigma: interface 3 lies at y = 0.25; allowed: above the interface below it (y = 0.5) and below y_max = 1, by increasing y" "Geometry/Interfaces above Sigma=0.5; 0.25"
run "interface crack touching Gamma_D" "Geometry/Interfaces above Sigma: interface 2 = '-1, 0.5' reaches the left side (x = -1), which is clamped" "Geometry/Interfaces above Sigma=0.5: -1, 0.5"
run "load does not parse" "Loads/Layer 1/Traction on bottom side: cannot evaluate '0; c*'" "Loads/Layer 1/Traction on bottom side=0; c*"
run "load evaluates to NaN" "Loads/Layer 1/Traction on bottom side must be finite on the bottom side" "Loads/Layer 1/Traction on bottom side=0; sqrt(x-5)"
run "prescribed displacement infinite" "Loads/Layer 2/Prescribed displacement must be finite on the left side" "Loads/Layer 2/Prescribed displacement=0; 1/(x-x)"
run "load on an absent layer" "Loads/Layer 2/Traction on top side must be '0; 0': layer 2 is absent (Materials/Number of layers = 1)" "Loads/Layer 2/Traction on top side=0; 1" --set "Materials/Number of layers=1"
# Body forces and eigenstrains: the number of components and the parse when
# read; a value that is not finite where it is evaluated (the assembly,
# after the output directory was staged: staging removed, one line, exit 1).
run "body force of three components" "Loads/Layer 1/Body force must have two components separated by ';' (x-component; y-component), got '0; 1; 2'" "Loads/Layer 1/Body force=0; 1; 2"
run "eigenstrain of two components" "Loads/Layer 2/Eigenstrain must have three components separated by ';' (eps11; eps22; eps12), got '1e-3; 0'" "Loads/Layer 2/Eigenstrain=1e-3; 0"
run "body force does not parse" "Loads/Layer 1/Body force: cannot evaluate '0; c*'" "Loads/Layer 1/Body force=0; c*"
run "eigenstrain NaN everywhere" "Loads/Layer 1/Eigenstrain is not finite at (x, y) = (" "Loads/Layer 1/Eigenstrain=log(x-10); 0; 0"
run "body force infinite" "Loads/Layer 2/Body force is not finite at (x, y) = (" "Loads/Layer 2/Body force=0; 1/(x-x)"
run "prescribed displacement on an absent layer" "Loads/Layer 2/Prescribed displacement must be '0; 0': layer 2 is absent (Materials/Number of layers = 1)" "Loads/Layer 2/Prescribed displacement=1e-4; 0" --set "Materials/Number of layers=1"
run "constant of an absent layer" "Loads/Constants: 'd = 1e-3*mu2' uses mu2, a constant of layer 2, which is absent (Materials/Number of layers = 1)" "Loads/Constants=c = 1e-3*mu1; d = 1e-3*mu2" --set "Materials/Number of layers=1"
run "eigenstrain on an absent layer" "Loads/Layer 2/Body force and Loads/Layer 2/Eigenstrain must be zero ('0; 0', '0; 0; 0'): layer 2 is absent (Materials/Number of layers = 1)" "Loads/Layer 2/Eigenstrain=1e-3; 0; 0" --set "Materials/Number of layers=1"
# Thermal loads (issue 32): Materials/Layer k/Thermal expansion (one number,
# or three for orthotropic and anisotropic laws, finite) and Loads/Temperature
# change (one expression, finite where evaluated, no constant of a layer
# that does not define it).
run "thermal expansion of two numbers" "Materials/Layer 1/Thermal expansion must be one number alpha [1/K] (Law = isotropic), finite, got '1e-5, 2e-5'" "Materials/Layer 1/Thermal expansion=1e-5, 2e-5"
run "three thermal expansions of an isotropic layer" "Materials/Layer 2/Thermal expansion must be one number alpha [1/K] (Law = isotropic)" "Materials/Layer 2/Thermal expansion=1e-5, 1e-5, 1e-5"
run "orthotropic thermal expansion of two numbers" "Materials/Layer 2/Thermal expansion must be one number alpha or three 'alpha_1, alpha_2, alpha_3' in the material axes [1/K] (Law = orthotropic)" "Materials/Layer 2/Law=orthotropic" --set "Materials/Layer 2/Thermal expansion=1e-5, 2e-5"
run "thermal expansion not a number" "Materials/Layer 1/Thermal expansion: cannot read 'hot' as a number" "Materials/Layer 1/Thermal expansion=hot"
run "thermal expansion infinite" "Materials/Layer 1/Thermal expansion: 'inf' is outside the range of normal double numbers" "Materials/Layer 1/Thermal expansion=inf"
run "side thermal expansion of two numbers" "Materials/Layer 1/Omega+/Thermal expansion must be one number alpha [1/K] (Law = isotropic)" "Materials/Layer 1/Omega+/Thermal expansion=1e-5, 2e-5"
run "temperature change of two components" "Loads/Temperature change must have one component, no ';' (dT), got '1; 2'" "Loads/Temperature change=1; 2"
run "temperature change does not parse" "Loads/Temperature change: cannot evaluate 'c*'" "Loads/Temperature change=c*"
run "temperature change NaN" "Loads/Temperature change is not finite at (x, y) = (" "Loads/Temperature change=log(x-10)" --set "Materials/Layer 1/Thermal expansion=1e-5"
# ... also where no material expands (every coefficient 0: the thermal load
# of each subproblem is built, its eigenstrain 0, and dT checked where it
# would be evaluated), and on the side that does not expand.
run "temperature change 0/0, no expansion" "Loads/Temperature change is not finite at (x, y) = (" "Loads/Temperature change=0/0"
run "temperature change log(x-100), no expansion" "Loads/Temperature change is not finite at (x, y) = (" "Loads/Temperature change=log(x-100)"
run "temperature change infinite, no expansion" "Loads/Temperature change is not finite at (x, y) = (" "Loads/Temperature change=20*(1 + y/(x-x))" --set "Materials/Number of layers=1"
run "temperature change NaN below Sigma, Omega+ expands" "Loads/Temperature change is not finite at (x, y) = (" "Loads/Temperature change=log(y)" --set "Materials/Layer 1/Omega+/Thermal expansion=1e-5"
# Friction on the crack faces: a Tresca bound g(x, y, s) >= 0 and finite at
# every crack node (here g = x: negative at the first crack node of the
# 16-cell mesh, x = -0.375; refused when the multiplier set is built), one
# component, an expression of x, y and s; a coefficient F >= 0; 1 to 100000
# fixed-point iterations; friction only between faces that cannot
# penetrate.
run "Tresca bound negative on the crack" "Contact/Friction bound must be finite and >= 0 on the crack, got -0.375 at (x, y) = (-0.375, 0)" "Contact/Friction=tresca" --set "Contact/Friction bound=x"
run "Tresca bound negative near the right tip" "Contact/Friction bound must be finite and >= 0 on the crack, got -0.0125 at (x, y) = (0.375, 0)" "Contact/Friction=tresca" --set "Contact/Friction bound=0.1*(0.25 - s)" --set "Mesh/Cells along Sigma=16"
run "Tresca bound not finite" "Contact/Friction bound must be finite and >= 0 on the crack, got" "Contact/Friction=tresca" --set "Contact/Friction bound=log(x-10)"
run "Tresca bound infinite at s = 0" "Contact/Friction bound must be finite and >= 0 on the crack, got inf at (x, y) = (0, 0)" "Contact/Friction=tresca" --set "Contact/Friction bound=1/abs(s)"
run "Tresca bound of two components" "Contact/Friction bound must have one component, no ';', got '0.01; 0.02'" "Contact/Friction=tresca" --set "Contact/Friction bound=0.01; 0.02"
run "Tresca bound does not parse" "Contact/Friction bound: cannot evaluate '0.01*(' as a function of x, y and s" "Contact/Friction=tresca" --set "Contact/Friction bound=0.01*("
run "Tresca bound uses a load constant" "Contact/Friction bound: cannot evaluate 'c*x' as a function of x, y and s" "Contact/Friction=tresca" --set "Contact/Friction bound=c*x"
run "Coulomb coefficient negative" "--set Contact/Friction coefficient=-0.3: The string <-0.3> does not match the given pattern" "Contact/Friction=coulomb" --set "Contact/Friction coefficient=-0.3"
run "Coulomb coefficient NaN" "--set Contact/Friction coefficient=nan: The string <nan> does not match the given pattern" "Contact/Friction=coulomb" --set "Contact/Friction coefficient=nan"
run "Friction iterations 0" "--set Contact/Friction iterations=0: The string <0> does not match the given pattern <[Integer range 1...100000 (inclusive)]>" "Contact/Friction=coulomb" --set "Contact/Friction iterations=0"
run "unknown friction law" "--set Contact/Friction=Coulomb: The string <Coulomb> does not match the given pattern <[Selection none|tresca|coulomb ]>" "Contact/Friction=Coulomb"
run "Tresca friction without non-penetration" "Contact/Friction = tresca needs Contact/Non-penetration on the crack = true" "Contact/Friction=tresca" --set "Contact/Friction bound=0.01" --set "Contact/Non-penetration on the crack=false"
run "Coulomb friction without non-penetration" "Contact/Friction = coulomb needs Contact/Non-penetration on the crack = true" "Contact/Friction=coulomb" --set "Contact/Friction coefficient=0.3" --set "Contact/Non-penetration on the crack=false"
# Crack growth (Fracture/Crack growth): load factors that are no list of
# numbers >= 0 or no start:step:end, that do not increase, more than one
# with a sweep or other than 1 without growth; growth with friction, with
# adaptive refinement, without a crack tip, with a toughness <= 0 at a tip,
# with a tip number that does not exist; the output entries of growth.
run "load factor not a number" "Loads/Load factor must be a ','-separated list of numbers >= 0 or start:step:end" "Loads/Load factor=1, x" --set "Fracture/Crack growth=quasi-static"
run "load factor negative" "Loads/Load factor must be a ','-separated list of numbers >= 0" "Loads/Load factor=-1" --set "Fracture/Crack growth=quasi-static"
run "load factor range with step 0" "start:step:end with 0 <= start <= end and step > 0" "Loads/Load factor=0:0:2" --set "Fracture/Crack growth=quasi-static"
run "load factor range of too many steps" "(at most 100000 factors)" "Loads/Load factor=0:1e-9:1" --set "Fracture/Crack growth=quasi-static"
run "load factors that decrease" "Loads/Load factor must increase with Fracture/Crack growth = quasi-static" "Loads/Load factor=1, 0.5" --set "Fracture/Crack growth=quasi-static"
run "load factor without growth" "Loads/Load factor must be 1 without Fracture/Crack growth" "Loads/Load factor=2"
run "sweep with two load factors" "Fracture/Crack growth = sweep needs one Loads/Load factor" "Loads/Load factor=1, 2" --set "Fracture/Crack growth=sweep"
run "growth whose load factors scale nothing" "Loads/Load factor scales = thermal: the scene has no such load, so the load factors change nothing" "Fracture/Crack growth=quasi-static" --set "Loads/Load factor=1, 2" --set "Loads/Load factor scales=thermal"
run "load factor scales misspelt" "Load factor scales" "Loads/Load factor scales=temperature"
run "growth with friction" "Fracture/Crack growth needs Contact/Friction = none" "Fracture/Crack growth=quasi-static" --set "Contact/Friction=tresca" --set "Contact/Friction bound=0.01"
run "growth with adaptive refinement" "Fracture/Crack growth needs Mesh/Refinement = global" "Fracture/Crack growth=sweep" --set "Mesh/Refinement=adaptive"
run "growth without G" "Fracture/Crack growth needs Fracture/Energy release rate = true" "Fracture/Crack growth=sweep" --set "Fracture/Energy release rate=false"
run "toughness negative at a tip" "Fracture/Toughness must be finite and > 0 on Sigma, got -1 at (x, y) = (-1, 0)" "Fracture/Crack growth=quasi-static" --set "Fracture/Toughness=x"
run "mode II toughness zero" "Fracture/Mode II toughness must be finite and > 0 on Sigma, got 0" "Fracture/Crack growth=quasi-static" --set "Fracture/Mixed-mode law=mode independent" --set "Fracture/Mode II toughness=0" --set "Fracture/Mixed-mode law=Benzeggagh-Kenane"
run "toughness does not parse" "Fracture/Toughness: cannot evaluate '1*(' as a function of x, y and s" "Fracture/Crack growth=quasi-static" --set "Fracture/Toughness=1*("
run "mixed-mode exponent zero" "Fracture/Mixed-mode exponent must be > 0, got 0" "Fracture/Crack growth=quasi-static" --set "Fracture/Mixed-mode exponent=0"
run "growing tip that does not exist" "Fracture/Growing tips: tip 3 does not exist, the crack has 2 tip(s)" "Fracture/Crack growth=sweep" --set "Fracture/Growing tips=3"
run "growing tips not numbers" "Fracture/Growing tips must be all or a ','-separated list of tip numbers >= 1, got first" "Fracture/Crack growth=sweep" --set "Fracture/Growing tips=first"
run "growth increment 0" "--set Fracture/Growth increment=0: The string <0> does not match the given pattern" "Fracture/Crack growth=sweep" --set "Fracture/Growth increment=0"
run "growth without a crack" "Fracture/Crack growth needs a crack with a tip inside Omega" "Fracture/Crack growth=sweep" --set "Geometry/Crack interval on Sigma=0, 0"
run "written steps misspelt" "Output/Written steps must be 'every N' (N >= 1), 'last' or 'none', got 'every'" "Output/Written steps=every"
run "displacement point of one coordinate" "Output/Displacement points must be 'x1, y1; x2, y2; ...' (finite numbers), got '0.5'" "Output/Displacement points=0.5"
run "displacement point outside the domain" "Output/Displacement points: (3, 0.5) lies outside the domain" "Fracture/Crack growth=sweep" --set "Output/Displacement points=3, 0.5"
run "temperature change using E2 of an orthotropic layer" "Loads/Temperature change: '1e-3*E2' uses E2, a constant of isotropic layers only (E2, nu2, mu2, lambda2), but Materials/Layer 2/Law = orthotropic" "Materials/Layer 2/Law=orthotropic" --set "Loads/Temperature change=1e-3*E2"
run "missing mesh file" "Mesh/Mesh files: cannot open" "Mesh/Mesh files=nothere_{side}.msh"
run "mesh file is a directory" "Mesh/Mesh files: cannot open 'mesh_dir_minus': not a regular file" "Mesh/Mesh files=mesh_dir_{side}"
# Broken meshes (Gmsh format 2.2, three columns of two triangles per half
# square): a slit (cells that do not share an interior edge) and an
# overlap (a cell listed twice) are refused when read.
cat > make_mesh.py <<'PYTHON'
import sys
def msh(nodes, tris, path):
    with open(path, 'w') as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for i, (x, y) in enumerate(nodes):
            f.write("%d %r %r 0\n" % (i + 1, x, y))
        f.write("$EndNodes\n$Elements\n%d\n" % len(tris))
        for i, t in enumerate(tris):
            f.write("%d 2 2 1 1 %d %d %d\n" % (i + 1, t[0] + 1, t[1] + 1, t[2] + 1))
        f.write("$EndElements\n")
def half(y0, y1, kind):
    xs = [-1, -0.5, 0.5, 1]
    nodes = [(x, y0) for x in xs] + [(x, y1) for x in xs]
    tris = []
    for i in range(3):
        a, b, c, d = i, i + 1, 4 + i + 1, 4 + i
        tris += [(a, b, c), (a, c, d)]
    if kind == "slit":
        # column 0 gets its own copies of the nodes at x = -0.5
        nodes += [(-0.5, y0), (-0.5, y1)]
        tris[0] = (0, 8, 9); tris[1] = (0, 9, 4)
    if kind == "inverted":
        a, b, c = tris[2]; tris[2] = (a, c, b)
    if kind == "overlap":
        tris.append(tris[0])
    return nodes, tris
kind = sys.argv[1]
for side, (y0, y1) in (("minus", (-1, 0)), ("plus", (0, 1))):
    n, t = half(y0, y1, kind if side == "minus" else "valid")
    msh(n, t, "%s_%s.msh" % (kind, side))
PYTHON
python3 make_mesh.py slit
python3 make_mesh.py overlap
before=$(snapshot)
run "mesh with a slit" "has a boundary face inside its subdomain at (-0.5, -0.5)" "Mesh/Mesh files=slit_{side}.msh"
run "mesh with overlapping cells" "overlap_minus.msh' does not fill (-1, 1) x (-1, 0)" "Mesh/Mesh files=overlap_{side}.msh"
run "theta <= 0" "Solver/Uzawa step theta must be a number > 0 or 'auto', got '-1'" "Solver/Uzawa step theta=-1"
run "theta = 0" "Solver/Uzawa step theta must be > 0 or 'auto', got 0" "Solver/Uzawa step theta=0"
run "bound p <= 0" "Contact/Multiplier bound p must be > 0, got 0" "Contact/Multiplier bound p=0"
run "crack end not a vertex, plus side" "Mesh/Cells along Sigma on the plus side = 3 does not make the crack end point" "Mesh/Cells along Sigma on the plus side=3"
run "crack end not a vertex, proposals" "numbers of cells that do: 4 8 12" "Mesh/Cells along Sigma=6"
check "crack tips that cannot be fitted" "Mesh/Fit crack tips: Mesh/Cells along Sigma = 2 has 1 vertices inside Sigma for 2 crack end points; allowed: at least 3" "$prm" --set "Output/Output directory=fresh/out" --set "Mesh/Fit crack tips=true" --set "Mesh/Cells along Sigma=2"
[[ ! -e fresh ]] || fail "crack tips that cannot be fitted" "'fresh' left behind"
run "support of theta beyond the outer boundary" "Fracture/Support radius = 5 reaches another tip, a corner of Sigma or the outer boundary from the crack tip at (x, y) = (-0.5, 0); allowed: (0, 0.5), or 0 (automatic)" "Fracture/Support radius=5"
run "negative support radius" "Fracture/Support radius=-1" "Fracture/Support radius=-1"
run "negative mode split length" "Fracture/Mode split length=-1" "Fracture/Mode split length=-1"
# A support of theta with too few cells (G would tend to 0 with R): the
# entry, the cells it holds, the radii and numbers of cells that would do.
run "support radius below the cell size" "Fracture/Support radius = 0.01 at the crack tip at x = -0.5 holds 0.08 cells of the mesh of Omega- along its radius (cells of size 0.125 at the tip on cycle 0): G needs at least 1 (R >= the cell size, else G tends to 0 with R): use Fracture/Support radius in [0.125, 0.5), or at least 200 Mesh/Cells along Sigma" "Fracture/Support radius=0.01"
run "support radius below the last cycle's cells" "0.0625 on the last cycle" "Fracture/Support radius=0.05" --set "Mesh/Number of cycles=2"

# Constants and expressions that clash with the parser's names or sizes.
for name in x y t sin E1 mu2; do
  run "constant named $name" "Loads/Constants: the name '$name' is reserved" "Loads/Constants=$name = 1"
done
long=$(printf '1+%.0s' $(seq 15000))1
run "constant of 30 000 characters" "Loads/Constants: longer than 10000 characters" "Loads/Constants=c = $long"
run "traction of 30 000 characters" "Loads/Layer 1/Traction on top side: longer than 10000 characters" "Loads/Layer 1/Traction on top side=0; $long"
run "constant not a name" "Loads/Constants must read 'name = expression" "Loads/Constants=2c = 1"
run "constant not finite" "Loads/Constants: constant 'c' = '1/0' is not a finite number" "Loads/Constants=c = 1/0"

# Numbers outside the range of double, and scenes beyond the memory.
run "denormal modulus" "Materials/Layer 1/Young's modulus: '1e-320' is outside the range of normal double numbers" "Materials/Layer 1/Young's modulus=1e-320"
run "denormal tolerance" "Solver/Tolerance: '4e-310' is outside the range of normal double numbers" "Solver/Tolerance=4e-310"
run "denormal corner" "Geometry/Lower left corner: '-1e-315' is outside the range" "Geometry/Lower left corner=-1e-315, -1"
run "huge corners" "Geometry: the corners and the height of Sigma must lie within +-1e100" "Geometry/Lower left corner=-1e300, -1e300" --set "Geometry/Upper right corner=1e300, 1e300"
run "tiny Omega" "Geometry: Omega must be at least 1e-100 wide and high" "Geometry/Lower left corner=-1e-300, -1e-300" --set "Geometry/Upper right corner=1e-300, 1e-300" --set "Geometry/Crack interval on Sigma=-5e-301, 5e-301"
run "modulus 1e308" "the stiffness matrix of subproblem u- has entries that are not finite: Materials/Layer 1/Young's modulus" "Materials/Layer 1/Young's modulus=1e308"
run "100000 cells along Sigma" "cycle 0 would have 1e+10 cells" "Mesh/Cells along Sigma=100000"
run "the refusal names the entries and the override" "use fewer cells or cycles (Mesh/Cells along Sigma, Mesh/Cells across each subdomain, Mesh/Number of cycles) or adaptive refinement; Mesh/Refuse above available memory = false runs it anyway" "Mesh/Cells along Sigma=100000"
# Loads whose energy (and the squares of the residuals) double precision
# cannot represent: the entry, its largest value and the way out.
run "loads of 1e160" "Loads/Layer 1/Traction on bottom side reaches 1e+160 at (-1, -1): the energy of such a load, about t^2 D^2 / E = 10^318, is above 10^290" "Loads/Constants=c = 1e160"
run "loads of 1e-160" "Loads/Layer 1/Traction on bottom side reaches 1e-160 at (-1, -1): the energy of such a load, about t^2 D^2 / E = 10^-322, is below 10^-290" "Loads/Constants=c = 1e-160"
run "prescribed displacement of 1e150" "Loads/Layer 1/Prescribed displacement reaches 1e+150" "Loads/Layer 1/Prescribed displacement=1e150; 0"
run "40 cycles of global refinement" "cycle 39 would have" "Mesh/Number of cycles=40"
run "many cells across" "GiB of memory, but" "Mesh/Cells across each subdomain=100000" --set "Mesh/Cells along Sigma=4096"

# Output directories that would take the user's files with them.
mkdir -p sub
ln -s keep link_to_keep
ln -s nowhere dangling
echo x > plainfile
before=$(snapshot)
for dir in "." ".." "./" "$work" "$work/." "$work/" "sub/.." "../$(basename "$work")" "$(dirname "$work")" "/"; do
  check "output directory '$dir'" "Output/Output directory" "$prm" --set "Output/Output directory=$dir"
done
check "output directory holding foreign files" "'keep' holds files that bilayer did not write" \
  "$prm" --set "Output/Output directory=keep"
check "output directory holding a file added to bilayer's" "'out' holds files that bilayer did not write ('notes.txt')" \
  "$prm" --set "Output/Output directory=out"
mkdir -p lookalike && echo '{"mine": 1}' > lookalike/summary.json && echo 'a,b' > lookalike/table.csv
: > empty.lock
before=$(snapshot)
check "output directory holding files named like bilayer's" "and no marker file .bilayer-output of a bilayer run); bilayer replaces" \
  "$prm" --set "Output/Output directory=lookalike"
check "a foreign (empty) DIR.lock" "'empty.lock' exists and is not a lock file of bilayer" \
  "$prm" --set "Output/Output directory=empty"
check "refusal after staging leaves no created parent" "Mesh/Cells along Sigma = 5 does not make the crack end point" \
  "$prm" --set "Output/Output directory=new/deeper/out" --set "Mesh/Cells along Sigma=5"
[[ ! -e new ]] || fail "refusal after staging leaves no created parent" "'new' left behind"
check "output directory holding foreign subdirectory" "'keep/sub/..' holds files that bilayer did not write" \
  "$prm" --set "Output/Output directory=keep/sub/.."
check "output directory through a symbolic link" "is a symbolic link" "$prm" --set "Output/Output directory=link_to_keep"
check "output directory a dangling symbolic link" "is a symbolic link" "$prm" --set "Output/Output directory=dangling"
check "output directory is a file" "'plainfile' exists and is not a directory" "$prm" --set "Output/Output directory=plainfile"
check "output directory not writable" "Output/Output directory: cannot create" "$prm" --set "Output/Output directory=/dev/null/x"
mkdir -p inputs/meshes && cp "$prm" inputs/scene.prm
printf 'include inputs/scene.prm\n' > including.prm
cp "$(dirname "$prm_source")"/../meshes/table1_P12_M32_minus.msh inputs/meshes/m_minus.msh
cp "$(dirname "$prm_source")"/../meshes/table1_P12_M32_plus.msh inputs/meshes/m_plus.msh
before=$(snapshot)
check "output directory holding the parameter file" "contains the input file 'inputs/scene.prm'" \
  inputs/scene.prm --set "Output/Output directory=inputs"
check "output directory is the parameter file" "is the input file 'inputs/scene.prm'" \
  inputs/scene.prm --set "Output/Output directory=inputs/scene.prm"
check "output directory holding an included file" "contains the input file 'inputs/scene.prm'" \
  including.prm --set "Output/Output directory=inputs"
check "output directory holding a mesh file" "contains the input file 'inputs/meshes/m_minus.msh'" \
  "$prm" --set "Mesh/Mesh files=inputs/meshes/m_{side}.msh" --set "Output/Output directory=inputs/meshes"

# A second run into a directory that a first run is writing: refused at
# once, naming the other process; the first run completes.
"$bilayer" "$prm" --set "Output/Output directory=busy" --set "Mesh/Cells along Sigma=96" \
  --set "Solver/Method=uzawa" > first.out 2>&1 &
first=$!
for _ in $(seq 100); do [[ -s busy.lock ]] && break; sleep 0.05; done
"$bilayer" "$prm" --set "Output/Output directory=busy" > stdout 2> stderr
rc=$?
if [[ $rc -eq 1 && $(wc -l < stderr) -eq 1 ]] && grep -qE "'busy' is being written by another run \(process $first " stderr; then
  echo "second run into a busy directory refused: yes"
else
  fail "second run into a busy directory refused" "exit status $rc"
fi
wait $first
rc=$?
if [[ $rc -eq 0 && -f busy/summary.json && ! -e busy.partial && ! -e busy.lock ]]; then
  echo "first run completes: yes"
else
  fail "first run completes" "exit status $rc"
  cat first.out
fi
rm -rf busy first.out
rm out/notes.txt
before=$(snapshot)

# A run that fails its checks (iteration limit): exit 2, the output
# directory unchanged, the failed run's results in out.failed.
"$bilayer" "$prm" --set "Output/Output directory=out" --set "Solver/Maximum iterations=10" > stdout 2> stderr
rc=$?
if [[ $rc -eq 2 ]] && grep -qF "bilayer: cycle 0 FAILED" stderr && [[ -f out.failed/summary.json ]] \
  && [[ "$(snapshot)" == "$before" && ! -e out.partial ]]; then
  echo "failed run leaves the output directory unchanged, results in out.failed: yes"
else
  fail "failed run leaves the output directory unchanged" "exit status $rc"
fi
rm -rf out.failed
before=$(snapshot)

# A write that fails (file size limit, as on a full disk): one line naming
# the file and the reason, the output directory unchanged, nothing staged.
# (Open MPI's PMIx keeps its data in a shared file unless told otherwise,
# which the limit would stop.)
(trap '' XFSZ; ulimit -f 600; PMIX_MCA_gds=hash exec "$bilayer" "$prm" --set "Output/Output directory=out" \
  --set "Mesh/Cells along Sigma=128" --set "Solver/Method=active set" > stdout 2> stderr)
rc=$?
if [[ $rc -eq 1 && $(wc -l < stderr) -eq 1 ]] && grep -qE "bilayer: error: writing the results of cycle 0 failed: cannot write '.*': File too large" stderr \
  && [[ "$(snapshot)" == "$before" && -z $(find . \( -name '*.partial' -o -name '*.lock' \) ! -path ./empty.lock) ]]; then
  echo "failed write leaves the output directory unchanged: yes"
else
  fail "failed write leaves the output directory unchanged" "exit status $rc"
fi

# A full disk (a small tmpfs, where this machine lets the test mount one):
# results that cannot fit are refused before the run; a disk that fills
# during the writes ends the run with one line naming the file and "No
# space left on device", and nothing staged.
mkdir -p small_disk
if mount -t tmpfs -o size=88k tmpfs small_disk 2> /dev/null; then
  trap 'umount "$work/small_disk" 2> /dev/null; rm -rf "$work"' EXIT
  check "output directory is a mount point" "'small_disk' is a mount point" \
    "$prm" --set "Output/Output directory=small_disk"
  check "results larger than the free space" "are free on its file system" \
    "$prm" --set "Output/Output directory=small_disk/out" --set "Mesh/Cells along Sigma=64"
  "$bilayer" "$prm" --set "Output/Output directory=small_disk/out" > stdout 2> stderr
  rc=$?
  if [[ $rc -eq 1 && $(wc -l < stderr) -eq 1 ]] && grep -qE "bilayer: error: writing the results of cycle 0 failed: cannot write '.*': No space left on device" stderr \
    && [[ -z $(ls -A small_disk) ]]; then
    echo "disk full during the writes: yes"
  else
    fail "disk full during the writes" "exit status $rc"
  fi
  umount small_disk
else
  echo "full disk: skipped (no tmpfs mount here)"
fi
rmdir small_disk
before=$(snapshot)

# An allocation that fails during the run (address space limited below
# what the factorisations need): one FAILED line naming the memory, the
# results so far in out.failed, the output directory unchanged; or, where
# the estimate already sees that the scene cannot fit, one refusal.
# (Not under AddressSanitizer, which reserves terabytes of address space.)
if [[ -n "${ASAN_OPTIONS:-}" ]]; then
  echo "allocation failure ends the run cleanly: skipped under AddressSanitizer"
else
(ulimit -v 1000000; exec "$bilayer" "$prm" --set "Output/Output directory=out" \
  --set "Mesh/Cells along Sigma=256" --set "Solver/Method=active set" > stdout 2> stderr)
rc=$?
if { [[ $rc -eq 2 ]] && grep -qF "FAILED: out of memory" stderr && [[ -d out.failed ]]; } \
  || { [[ $rc -eq 1 && $(wc -l < stderr) -eq 1 ]] && grep -qF "of memory, but" stderr; }; then
  [[ "$(snapshot)" == "$before" && -z $(find . \( -name '*.partial' -o -name '*.lock' \) ! -path ./empty.lock) ]] \
    && echo "allocation failure ends the run cleanly: yes" \
    || fail "allocation failure ends the run cleanly" "files changed"
else
  fail "allocation failure ends the run cleanly" "exit status $rc"
fi
fi
rm -rf out.failed

# Many BLAS threads under an address-space limit: the refusal names the
# memory the OpenBLAS threads map and the variables to set, and the process
# ends (its threads cannot map their work buffers and would retry for ever).
if [[ -n "${ASAN_OPTIONS:-}" ]]; then
  echo "BLAS threads under ulimit -v: skipped under AddressSanitizer"
elif ! "$bilayer" --version 2>/dev/null | grep -q OpenBLAS; then
  echo "BLAS threads under ulimit -v: skipped (the BLAS is not OpenBLAS)"
else
  for threads in "OPENBLAS_NUM_THREADS=40" "BILAYER_BLAS_THREADS=40"; do
    (ulimit -v 600000; exec env "$threads" timeout 60 "$bilayer" "$prm" \
      --set "Output/Output directory=fresh/out" > stdout 2> stderr)
    rc=$?
    if [[ $rc -eq 1 && $(wc -l < stderr) -eq 1 ]] && grep -qF "address-space limit (ulimit -v)" stderr \
      && grep -qF "each OpenBLAS thread maps a work buffer of 128 MiB" stderr \
      && grep -qF "OPENBLAS_NUM_THREADS=1" stderr && [[ ! -e fresh && "$(snapshot)" == "$before" ]]; then
      echo "BLAS threads under ulimit -v ($threads): yes"
    else
      fail "BLAS threads under ulimit -v ($threads)" "exit status $rc"
    fi
  done
fi

# A mesh far beyond an address-space limit: the refusal names the mesh
# entries and not the BLAS threads (no thread count would make room).
if [[ -z "${ASAN_OPTIONS:-}" ]]; then
  (ulimit -v 4000000; exec timeout 60 "$bilayer" "$prm" --set "Mesh/Cells along Sigma=100000" \
    --set "Output/Output directory=fresh/out" > stdout 2> stderr)
  rc=$?
  if [[ $rc -eq 1 && $(wc -l < stderr) -eq 1 ]] && grep -qF "address-space limit (ulimit -v)" stderr \
    && grep -qF "Mesh/Cells along Sigma" stderr && grep -qF "Mesh/Number of cycles" stderr \
    && ! grep -qF "fewer BLAS threads" stderr && [[ ! -e fresh && "$(snapshot)" == "$before" ]]; then
    echo "a huge mesh under ulimit -v: the mesh entries named, not the BLAS threads: yes"
  else
    fail "a huge mesh under ulimit -v: the mesh entries named, not the BLAS threads" "exit status $rc"
  fi
fi

# One member of each class that the hostile tests try in full
# (tests/cli/gmsh_refusals.sh, hostile_output.sh, script_outputs.sh,
# tests/support_cells.cc; the removed staging directory and the study
# scripts' folders are there only, as they need a run under way or a script).
scenes=$(dirname "$prm_source")
# A scene program: refused before gmsh runs, the command not run.
{ cat "$scenes/two_cracks.geo"; echo "SystemCall \"touch '$work/ran'\";"; } > program.geo
sed 's/two_cracks.geo/program.geo/' "$scenes/two_cracks.prm" > program.prm
# A curve in Sigma and in the crack: refused naming both groups.
sed 's/Physical Curve("Sigma") = {11, 13, 15};/Physical Curve("Sigma") = {11, 12, 13, 15};/' \
  "$scenes/two_cracks.geo" > both.geo
sed 's/two_cracks.geo/both.geo/' "$scenes/two_cracks.prm" > both.prm
# A folder with a marker that does not name it (forged, or copied).
mkdir -p forged
echo '{"mine": 1}' > forged/summary.json
printf 'This directory was written by bilayer.\nfile: summary.json\n' > forged/.bilayer-output
before=$(snapshot)
check "scene program (SystemCall)" "program.geo:" program.prm --set "Output/Output directory=fresh/out"
[[ ! -e ran ]] || fail "scene program (SystemCall)" "the command ran"
check "curve in Sigma and crack" "'Sigma' and 'crack'" both.prm --set "Output/Output directory=fresh/out"
# A temperature change of x, y on a Gmsh scene: refused as on the rectangle,
# with or without an expanding layer.
for alpha in 0 1e-5; do
  check "Gmsh scene, temperature change not finite (alpha $alpha)" "Loads/Temperature change is not finite at (x, y) = (" \
    "$scenes/two_cracks.prm" --set "Output/Output directory=fresh/out" --set "Loads/Temperature change=sqrt(x-1000)" \
    --set "Materials/Layer 1/Thermal expansion=$alpha"
done
check "forged output marker" "'forged'" "$prm" --set "Output/Output directory=forged"
DEAL_II_NUM_THREADS=abc check "DEAL_II_NUM_THREADS=abc" "DEAL_II_NUM_THREADS must be a whole number" \
  "$prm" --set "Output/Output directory=fresh/out"
(
  name=$(printf 'd%.0s' $(seq 200))
  mkdir -p deep && cd deep || exit 1
  for _ in $(seq 22); do mkdir "$name" && cd "$name" || exit 1; done
  "$bilayer" "$work/$prm" --set "Output/Output directory=$work/fresh/out" > "$work/stdout" 2> "$work/stderr"
) ; rc=$?
[[ $rc -eq 1 && $(wc -l < stderr) -eq 1 ]] && grep -qF "longer than PATH_MAX" stderr && [[ ! -e fresh ]] \
  && echo "working directory longer than PATH_MAX: yes" || fail "working directory longer than PATH_MAX" "exit status $rc"
rm -rf deep
# A backup copy beside the directory and a pipe that closes early: the run
# completes, the copy is kept byte for byte, nothing staged or locked.
cp -r out out.old && echo 'my note' > out.old/notes.txt
copy=$(cd out.old && find . -type f -print0 | sort -z | xargs -0 md5sum)
"$bilayer" "$prm" --set "Output/Output directory=out" --set "Solver/Method=active set" 2> stderr | head -1 > stdout
rc=${PIPESTATUS[0]}
[[ $rc -eq 0 && -f out/summary.json && ! -e out.partial && ! -e out.lock && $(wc -l < stdout) -eq 1 ]] \
  && [[ "$(cd out.old && find . -type f -print0 | sort -z | xargs -0 md5sum)" == "$copy" ]] \
  && echo "backup beside the directory kept, output piped into head -1: yes" \
  || fail "backup beside the directory kept, output piped into head -1" "exit status $rc"
rm -rf out.old forged program.* both.* ran

# A run that passes replaces bilayer's directory whole (the user's note was
# removed above), and removes an earlier failed run's results; blanks around --set
# values do not count.
"$bilayer" "$prm" --set "Output/Output directory=out" --set "Solver/Maximum iterations=10" > /dev/null 2>&1
"$bilayer" "$prm" --set "Output/Output directory = out " --set "Solver/Method = active set" > stdout 2> stderr
rc=$?
if [[ $rc -eq 0 && -f out/solution.pvd && -f out/.bilayer-output && ! -e out.partial && ! -e out.failed && ! -e "out " ]] \
  && grep -q '"solver": "active set"' out/summary.json; then
  echo "passing run replaces the output directory: yes"
else
  fail "passing run replaces the output directory" "exit status $rc"
fi
[[ $(cat keep/data.txt keep/sub/data.txt) == $'precious\nprecious' && $(find keep | wc -l) -eq 4 ]] \
  && echo "foreign directory untouched: yes" || fail "foreign directory untouched" "changed"

# Under mpirun -np 2: a Tresca bound that is negative on the crack is found
# by every process as it builds the (replicated) multiplier set; the first
# reports it in one line, none aborts, nothing is written.
if command -v mpirun > /dev/null; then
  mpirun -np 2 "$bilayer" "$prm" --set "Output/Output directory=fresh/out" \
    --set "Contact/Friction=tresca" --set "Contact/Friction bound=x" > stdout 2> stderr
  rc=$?
  why=""
  [[ $rc -eq 1 ]] || why="exit status $rc"
  [[ $(grep -c '^bilayer' stderr) -eq 1 ]] || why="$why; $(grep -c '^bilayer' stderr) lines of bilayer"
  grep -qF "bilayer: error: Contact/Friction bound must be finite and >= 0 on the crack, got -0.375 at (x, y) = (-0.375, 0)" stderr \
    || why="$why; $(head -1 stderr)"
  ! grep -qiE "MPI_ABORT|terminate called|stacktrace" stderr || why="$why; aborted"
  [[ ! -e fresh && -z $(find . \( -name '*.partial' -o -name '*.lock' \) ! -path ./empty.lock) ]] \
    || why="$why; wrote"
  if [[ -z $why ]]; then
    echo "Tresca bound negative on the crack under mpirun -np 2: yes"
  else
    fail "Tresca bound negative on the crack under mpirun -np 2" "$why"
  fi
fi

echo "failures: $failures"
[[ $failures -eq 0 ]]
