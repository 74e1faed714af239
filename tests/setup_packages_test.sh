#!/bin/bash
# The README's two commands install what they use, on a minimal Debian 12:
#  1. every program that scripts/run (and what it runs) calls, and every one
#     that scripts/test, .ci/run, the test scripts and the tests call, has an
#     entry in tests/external_programs.txt (program -> Debian package);
#  2. each comes from a package that the setup of that command installs
#     (scripts/setup; --for-tests for testing) or that a minimal Debian has;
#  3. the table agrees with dpkg wherever the package is installed here;
#  4. no package that scripts/run installs starts a system service.
# The calls are found in the sources: shell scripts by parsing them (shfmt),
# C++ and JavaScript by the forms the tests use to start a program (listed in
# cpp_calls and js_calls below); a call in another form is not seen.
# scripts/test-fresh-debian runs the commands on such a system for real.
#   tests/setup_packages_test.sh
set -euo pipefail
cd "$(dirname "$0")/.."
table=tests/external_programs.txt
for tool in shfmt jq dpkg-query; do
  command -v "$tool" >/dev/null || { echo "FAIL: $tool is not installed (scripts/setup --for-tests installs it)" >&2; exit 1; }
done
# Failures are counted in a file: some are found in subshells.
failures="$(mktemp)"
trap 'rm -f "$failures"' EXIT
fail() { echo "FAIL: $*" | tee -a "$failures" >&2; }

# The files, by the command that runs them. (Run: what scripts/run runs, and
# the m3055 it builds; test: the rest of what scripts/test and .ci/run run.)
run_shell=(scripts/run scripts/setup)
test_shell=(scripts/test scripts/test-web scripts/web scripts/test-sanitize scripts/sanitizer-tree scripts/fuzz
            scripts/test-noexplorer scripts/bench-capture .ci/run scripts/slurm/submit scripts/slurm/*.sbatch tests/*.sh)
mapfile -t run_cpp < <(find app grading renderer explore -name '*.cpp' -o -name '*.h' | sort)
test_cpp=(tests/*.cpp tests/support/*.cpp tests/fakes/*.c)
test_js=(tests/web/*.js)
test_cmake=(CMakeLists.txt tests/CMakeLists.txt)

# Shell: every simple command's words (an expansion reads "$NAME": a program
# named by a variable is the project's own), with the prefixes that run another
# program peeled off (timeout 30 bash ...; $sudo apt-get ...);
# `command -v X` counts as a call of X. Code in a string (bash -c, trap) is
# printed as {code} and parsed in turn. Prints {line, program} or {line, code}.
read -r -d '' shell_calls_jq <<'JQ' || true
def expansion: "$" + (.Param.Value? // "");
def text: [.Parts[]? |
  if .Type == "Lit" or .Type == "SglQuoted" then .Value
  elif .Type == "DblQuoted" then [.Parts[]? | if .Type == "Lit" then .Value | gsub("\\\\(?<c>[$`\"\\\\])"; .c) else expansion end] | join("")
  else expansion end] | join("");
def drop_options: if length > 0 and (.[0] | test("^(-.*|[0-9.]+[smhd]?|[A-Za-z_][A-Za-z0-9_]*=.*)$")) then .[1:] | drop_options else . end;
def calls:
  if length == 0 then empty
  elif .[0] == "$sudo" then .[1:] | calls
  elif .[0] == "command" and .[1] == "-v" then [.[2]]
  elif .[0] | IN("exec", "nohup", "setsid", "sudo", "env", "nice", "timeout", "chrt", "xvfb-run") then [.[0]], (.[1:] | drop_options | calls)
  else . end;
.. | objects | select(.Type? == "CallExpr") | .Pos.Line as $line | [.Args[]? | text] | calls |
  if (.[0] | IN("bash", "sh")) and .[1] == "-c" then {line: $line, program: .[0]}, {line: $line, code: .[2]}
  elif .[0] == "trap" and (.[1] // "-" | startswith("-") | not) then {line: $line, program: "trap"}, {line: $line, code: .[1]}
  else {line: $line, program: .[0]} end
JQ
declare -A builtin
for word in $(compgen -b; compgen -k); do builtin[$word]=1; done
shell_calls() {  # FILE...: prints "PROGRAM FILE:LINE" for each call
  local file code ast word
  for file; do
    ast="$(shfmt --to-json <"$file")" || { fail "shfmt cannot parse $file"; continue; }
    local -A function=()
    for word in $(jq -r '.. | objects | select(.Type? == "FuncDecl") | .Name.Value' <<<"$ast"); do function[$word]=1; done
    local queue=("$ast") lines=("") outer
    while ((${#queue[@]})); do
      ast="${queue[0]}" outer="${lines[0]}"
      queue=("${queue[@]:1}") lines=("${lines[@]:1}")
      while IFS=$'\t' read -r kind line value; do
        line="${outer:-$line}"  # in a string of code: the string's line
        if [ "$kind" = code ]; then
          code="$(base64 -d <<<"$value")"
          queue+=("$(shfmt --to-json <<<"$code")") || fail "shfmt cannot parse the code on $file:$line"
          lines+=("$line")
        elif [[ "$value" != *'$'* && -z "${function[$value]:-}" ]]; then
          echo "$value $file:$line"
        fi
      done < <(jq -r "$shell_calls_jq"' | if .code then ["code", .line, (.code | @base64)] else ["program", .line, .program] end | @tsv' <<<"$ast")
    done
  done
}
matches() {  # ERE FILE...: "NAME FILE:LINE" for each match, NAME its last word
  grep -onE "$1" "${@:2}" | sed -E 's/^([^:]*):([0-9]+):(.*[^A-Za-z0-9_.+-])?([A-Za-z0-9_.+-]+)["'"'"') ]*$/\4 \1:\2/'
}
name='[A-Za-z0-9_.+-]+'
cpp_calls() {  # FILE...
  matches "exec[lv]p?e?\(\"$name\"" "$@"                                    # execlp("Xvfb", ...)
  matches "(find_program|find_in_path|on_path|have_program)\(\"$name\"" "$@"  # looked for on $PATH
  matches "\"/usr/s?bin/$name\"|dir \+ \"/[A-Za-z0-9_+-]+\"" "$@"              # "/usr/bin/timeout"; dir + "/xvfb-run"
  matches "(command|cmd) = \"$name |(system|popen)\(\(?\"$name " "$@"         # a shell command's first word
  matches "timeout [0-9]+ $name|command -v $name" "$@"
}
js_calls() { matches "(execFileSync|execFile|execSync|spawnSync|spawn)\('$name'|'/usr/s?bin/$name'" "$@"; }
cmake_calls() { matches "COMMAND $name|find_program\([A-Z0-9_]+ $name" "$@"; }

# Where a call names a file of the repository, that file is ours: a script
# run this way must be one of the files read above.
called_here() {  # SCOPE NAME LOCATION
  local scope="$1" name="$2" where="$3"
  [ -z "${builtin[$name]:-}" ] || return 0
  if [[ "$name" == */* ]]; then
    if [ -f "$name" ]; then
      [[ " ${run_shell[*]} ${test_shell[*]} " == *" $name "* ]] ||
        fail "$where runs $name: add it to the files tests/setup_packages_test.sh reads"
      return
    fi
    name="$(basename "$name")"
  fi
  echo "$scope $name $where"
}
calls="$(
  { shell_calls "${run_shell[@]}"; cpp_calls "${run_cpp[@]}"; } | while read -r n w; do called_here run "$n" "$w"; done
  { shell_calls "${test_shell[@]}"; cpp_calls "${test_cpp[@]}"; js_calls "${test_js[@]}"; cmake_calls "${test_cmake[@]}"; } |
    while read -r n w; do called_here test "$n" "$w"; done
)"

# The table: "PROGRAM PACKAGE" ("-": built here), and the packages of a
# minimal Debian 12 on the line "minimal: ...".
declare -A package_of
minimal=" $(sed -n 's/^minimal://p' "$table" | tr -s ' \n' ' ') "
while read -r program package _; do
  [ -n "$program" ] && [ "$program" != minimal: ] && package_of[$program]="$package"
done < <(sed 's/#.*//' "$table")
run_set=" $(scripts/setup --print-packages | tr '\n' ' ') "
test_set=" $(scripts/setup --for-tests --print-packages | tr '\n' ' ') "

# 1 and 2.
while read -r scope program where; do
  package="${package_of[$program]:-}"
  if [ -z "$package" ]; then
    fail "$where calls $program, which has no entry in $table (PROGRAM PACKAGE; dpkg -S \"\$(command -v $program)\" names the package)"
    continue
  fi
  [ "$package" = - ] && continue
  [[ "$minimal" == *" $package "* || "$run_set" == *" $package "* ]] && continue
  if [ "$scope" = run ]; then
    fail "$where (run by scripts/run) calls $program, from $package, which scripts/setup does not install"
  elif [[ "$test_set" != *" $package "* ]]; then
    fail "$where calls $program, from $package, which scripts/setup --for-tests does not install"
  fi
done <<<"$calls"
for program in "${!package_of[@]}"; do
  grep -q " $program " <<<"$calls" || fail "$table: $program is called nowhere any more"
done

# 3. The package, where it is installed here, or one it depends on (a
# metapackage: imagemagick, lld; python3's python3-minimal) ships the program,
# or the file it resolves to (an alternative, a merged /usr).
owner() {  # PROGRAM: the package that ships the file it runs here, if any
  local path candidate package
  path="$(command -v "$1")" || path="$(compgen -G "/usr/sbin/$1")" || return 0
  path="$(readlink -f "$path")"
  for candidate in "$path" "${path#/usr}"; do
    package="$(dpkg-query -S "$candidate" 2>/dev/null | awk -F: '!/^diversion/ && !found { print $1; found = 1 }')"
    [ -z "$package" ] || { echo "$package"; return 0; }
  done
}
installed() { [ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null)" = "install ok installed" ]; }
owns() {  # PACKAGE PROGRAM
  grep -qE "/s?bin/$2\$" <(dpkg-query -L "$1" 2>/dev/null) && return 0
  local packages package
  packages="$1"$'\n'"$(dpkg-query -W -f='${Depends}, ${Pre-Depends}' "$1" | sed -E 's/ *\([^)]*\)//g; s/ *[|,] */\n/g')"
  for package in $packages; do
    grep -qE "/s?bin/$2\$" <(dpkg-query -L "$package" 2>/dev/null) && return 0
  done
  package="$(owner "$2")"
  [ -n "$package" ] && grep -qxF -- "$package" <<<"$packages"
}
for program in "${!package_of[@]}"; do
  package="${package_of[$program]}"
  [ "$package" = - ] && continue
  if ! installed "$package"; then
    echo "note: $package is not installed here: $table's $program -> $package not checked against dpkg"
  elif ! owns "$package" "$program"; then
    fail "$table: $program is not from $package here (dpkg -S: $(owner "$program"))"
  fi
done

# 4. A package whose service starts on install (an init script or a systemd
# unit: munge, slurmctld, slurmd) is for the tests only. (What these pull in
# is checked by scripts/test-fresh-debian on a minimal system.)
for package in $run_set; do
  if ! installed "$package"; then
    fail "$package (scripts/setup) is not installed here: cannot check that it has no service"
  elif service="$(dpkg-query -L "$package" | grep -E '^/etc/init\.d/.|^(/usr)?/lib/systemd/system/.*\.service$')"; then
    fail "scripts/setup (scripts/run) installs $package, which starts a service on install: $(echo $service)"
  fi
done

if [ -s "$failures" ]; then
  echo "FAIL: $(wc -l <"$failures") problem(s)" >&2
  exit 1
fi
echo "PASS: $(wc -l <<<"$calls") calls of $(cut -d' ' -f2 <<<"$calls" | sort -u | wc -l) programs, each installed by the setup of the command that runs it"
