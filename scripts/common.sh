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
# With --help or -h as the first argument, prints the help of the sourcing
# script and exits 0.

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

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

if [[ "${1:-}" == --help || "${1:-}" == -h ]]; then
  print_help "${BASH_SOURCE[1]:-$0}"
  exit 0
fi
