# Shared by the bash scripts of scripts/ (sourced, not run):
#   source "$(dirname "${BASH_SOURCE[0]}")/common.sh" "$@"
# Sets root (the repository) and defines
#   print_help [SCRIPT]          the leading comment block of SCRIPT (default:
#                                the calling script) without its '# '
#   missing_packages PACKAGE...  those of the Debian packages not installed
#   install_packages PACKAGE...  apt-get update (once per run) and install
#                                (sudo when not root), without questions
#   have_apt                     whether this machine installs packages with
#                                apt-get (Debian and derivatives)
#   missing_commands COMMAND...  those of the commands not in PATH
#   require TOOL...              exits 1 with one line "SCRIPT: TOOL is
#                                missing: install the Debian package
#                                PACKAGE" for the first TOOL not in PATH
#                                (import:NAME: a module Debian's python3
#                                cannot import; the packages:
#                                scripts/tool_packages.txt, as
#                                bilayer_run.require in Python)
#   output_folder SCRIPT DIR NAME...
#                                opens DIR as SCRIPT's output folder (created,
#                                or empty, or marked by SCRIPT itself: never
#                                a copy of one, never a folder of the user),
#                                claims the NAMEs in it (a file of the user
#                                of that name is refused) and prints DIR's
#                                absolute path; exits 1 with one line when
#                                it may not (scripts/bilayer_run.py output)
#   scene_entry PRM SECTION/ENTRY [--set S/E=v ...]
#                                the value of an entry as bilayer reads PRM
#                                (includes and --set applied)
#   safe_name PRM                the stem of PRM for a folder name, odd
#                                characters replaced ('..prm' is not '..')
#   build_bilayer                scripts/setup --no-install, quietly, unless
#                                the environment names the program (BILAYER)
# and bilayer, the program the scripts run: $BILAYER, else build/bilayer.
# With --help or -h as the first argument, prints the help of the sourcing
# script and exits 0.

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bilayer=${BILAYER:-$root/build/bilayer}
[[ $bilayer == /* ]] || bilayer=$PWD/$bilayer

# The comment lines after the #! line, up to the first line that is not a
# comment: the help of each script is its opening comment.
print_help() {
  local script=${1:-${BASH_SOURCE[1]:-$0}} line first=1
  while IFS= read -r line || [[ -n $line ]]; do
    if ((first)); then
      first=0
      [[ $line == '#!'* ]] && continue
    fi
    [[ $line == '#'* ]] || break
    line=${line#\#}
    printf '%s\n' "${line# }"
  done < "$script"
}

missing_packages() {
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2> /dev/null | grep -q "install ok installed" \
      || echo "$p"
  done
}

apt_updated=0
install_packages() {
  local sudo=()
  [[ $(id -u) -ne 0 ]] && sudo=(sudo)
  if ((!apt_updated)); then
    "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
    apt_updated=1
  fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q "$@"
}

have_apt() {
  command -v apt-get > /dev/null && command -v dpkg-query > /dev/null
}

missing_commands() {
  local c
  for c in "$@"; do
    command -v "$c" > /dev/null || echo "$c"
  done
}

require() {
  local tool name t rest package
  for tool in "$@"; do
    if [[ $tool == import:* ]]; then
      /usr/bin/python3 -c "import ${tool#import:}" 2> /dev/null && continue
      name="python3's ${tool#import:}"
    else
      command -v "$tool" > /dev/null && continue
      name=$tool
    fi
    package=${tool#import:}
    while read -r t rest; do
      if [[ $t == "$tool" ]]; then
        package=$rest
        break
      fi
    done < "$root/scripts/tool_packages.txt"
    if [[ $package == *" "* ]]; then
      echo "${0##*/}: $name is missing: install the Debian packages $package" >&2
    else
      echo "${0##*/}: $name is missing: install the Debian package $package" >&2
    fi
    exit 1
  done
}

output_folder() {
  python3 "$root/scripts/bilayer_run.py" output "$@"
}

scene_entry() {
  python3 "$root/scripts/bilayer_run.py" entry "$@"
}

safe_name() {
  python3 "$root/scripts/bilayer_run.py" name "$1"
}

build_bilayer() {
  [[ -n ${BILAYER:-} ]] || "$root/scripts/setup" --no-install > /dev/null
}

if [[ "${1:-}" == --help || "${1:-}" == -h ]]; then
  print_help "${BASH_SOURCE[1]:-$0}"
  exit 0
fi
