#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# tests/windows/run.sh LINUX_LUTKIT LUTKIT_EXE [WORKDIR]
# The Windows edition (lutkit.exe, scripts/build-windows.sh) under Wine against the Linux build,
# on the same inputs in the same run (docs/windows.md, "Tests"). Each case runs the same command
# line in two fresh copies of the inputs, one per program, and compares the exit codes, what was
# printed (paths spelled with / and timings blanked) and every file written, BYTE FOR BYTE (cmp).
# Then what only Windows has: the drop, paths with backslashes, a drive letter, spaces and
# non-ASCII names, a read-only folder, Ctrl-C, standard output in binary mode.
# ./test.sh runs it when mingw-w64 and wine are installed. Exit 0 when every case passed.
set -uo pipefail

# --- Cases known to differ, with the reason -----------------------------------------------------
# A case listed here is still run and compared: when it differs, it is reported with how much
# (tests/windows/diffstat.py) and does not fail the stage; when it matches, the stage says so, so
# the line can go. Remove a line once its reason is gone.
#   (none: the one reason there was, MinGW-w64's libm rounding differently from glibc's, is gone
#   since every build calls musl's maths compiled in: lut/Math.h, docs/portable.md)
KNOWN_DIVERGENT=(
)

here="$(cd "$(dirname "$0")" && pwd)"
lin="${1:?usage: tests/windows/run.sh LINUX_LUTKIT LUTKIT_EXE [WORKDIR]}"
exe="${2:?usage: tests/windows/run.sh LINUX_LUTKIT LUTKIT_EXE [WORKDIR]}"
W="${3:-$(mktemp -d)}"
case "$lin" in /*) ;; *) lin="$PWD/$lin" ;; esac
case "$exe" in /*) ;; *) exe="$PWD/$exe" ;; esac
case "$W" in /*) ;; *) W="$PWD/$W" ;; esac
root="$(cd "$here/../.." && pwd)"
data="$root/tests/data"
py=/usr/bin/python3 # Debian's, with numpy

# Wine: its own prefix, kept between runs (the first start builds it: ~15 s), quiet, no Mono or
# Gecko installer asked for, UTF-8 arguments; one wineserver for the whole stage.
export WINEPREFIX="${LUTKIT_WINEPREFIX:-$HOME/.cache/lutkit/wine}" WINEDEBUG=-all
export WINEDLLOVERRIDES="mscoree,mshtml=" LC_ALL=C.UTF-8
mkdir -p "$(dirname "$WINEPREFIX")"
t0=$(date +%s)
if ! wine "$exe" --version >/dev/null 2>"$W.wine-start.log"; then
  echo "windows: lutkit.exe does not start under wine:" >&2
  cat "$W.wine-start.log" >&2
  exit 1
fi
wineserver -p 120
echo "windows: wine ready in $(($(date +%s) - t0)) s ($(wine --version), prefix $WINEPREFIX)"

rm -rf "$W"
mkdir -p "$W/in" "$W/lin" "$W/win"
in="$W/in"
trap 'chattr -i "$W"/*/*/ro "$W"/ro* 2>/dev/null; wineserver -k 2>/dev/null' EXIT

failures=()
passed=0
known_seen=()
is_known() {
  local k
  for k in "${KNOWN_DIVERGENT[@]}"; do
    [ "${k%%:*}" = "$1" ] && return 0
  done
  return 1
}
fail() {
  failures+=("$1")
  echo "FAIL  $1"
}

# What both programs print, comparable: / for \, no drive letter, lutkit.exe as lutkit, then the
# times blanked by the rules tests/web/test_same_bytes.py blanks them by too
# (tests/common/timing-rules.sed: a number of ms or s, match's "time" line, files per second,
# JSON's "seconds").
normalize() {
  sed -E -e 's#\\#/#g' -e 's#[A-Z]:/#/#g' -e 's#lutkit\.exe#lutkit#g' \
    -f "$here/../common/timing-rules.sed" "$1" |
    if [ -n "${UNORDERED:-}" ]; then sort; else cat; fi
}

# both NAME [--rc N|any (default 0)] [--stdout-bytes] [--dir D] [--unordered] [--report-differs WHY] -- ARGS...
# lutkit ARGS in $W/lin/D (Linux) and $W/win/D (Windows), D = NAME unless given; a new D starts as
# a fresh copy of $in (hard links: lutkit never writes an input), a D given again is reused (the
# next step of a sequence). Printed output goes to $W/{lin,win}/NAME.{out,err}. --unordered: a
# batch's lines compared in any order (jobs finish as they finish, on Linux too); --report-differs:
# the files must match, the report may not, for the reason given (an edition difference).
both() {
  local name="$1" want=0 rawout=0 dir="$1"
  UNORDERED=""
  shift
  while [ "$1" != "--" ]; do
    case "$1" in
      --rc) want="$2"; shift 2 ;;
      --stdout-bytes) rawout=1; shift ;;
      --dir) dir="$2"; shift 2 ;;
      --unordered) UNORDERED=1; shift ;;
      --report-differs) rawout=2; echo "      $name: the report may differ: $2"; shift 2 ;;
      *) echo "both: bad option $1" >&2; exit 2 ;;
    esac
  done
  shift
  local l="$W/lin/$dir" w="$W/win/$dir"
  [ -d "$l" ] || cp -al "$in" "$l"
  [ -d "$w" ] || cp -al "$in" "$w"
  (cd "$l" && "$lin" "$@" >"$W/lin/$name.out" 2>"$W/lin/$name.err" </dev/null)
  local lrc=$?
  (cd "$w" && wine "$exe" "$@" >"$W/win/$name.out" 2>"$W/win/$name.err" </dev/null)
  local wrc=$?
  [ -z "${FIXUP:-}" ] || "$FIXUP" "$W/lin/$name.err"
  compare_case "$name" "$dir" "$lrc" "$wrc" "$want" "$rawout"
}

# winonly NAME [--dir D] -- ARGS...: lutkit.exe ARGS alone, in $W/win/D; exit code in NAME.rc.
winonly() {
  local name="$1" dir="$1"
  shift
  if [ "$1" = "--dir" ]; then
    dir="$2"
    shift 2
  fi
  shift
  local w="$W/win/$dir"
  [ -d "$w" ] || cp -al "$in" "$w"
  (cd "$w" && wine "$exe" "$@" >"$W/win/$name.out" 2>"$W/win/$name.err" </dev/null)
  echo $? >"$W/win/$name.rc"
}

# expect_win NAME RC REGEX: winonly NAME ended with RC, said REGEX (grep -E) and wrote nothing.
expect_win() {
  local name="$1" rc="$2" regex="$3"
  [ "$(cat "$W/win/$name.rc")" = "$rc" ] || { echo "         exit code $(cat "$W/win/$name.rc"), expected $rc"; return 1; }
  grep -Eq "$regex" "$W/win/$name.err" || { echo "         no '$regex' in: $(head -3 "$W/win/$name.err")"; return 1; }
  [ "$(cd "$W/win/$name" && find . -type f | sort)" = "$(cd "$in" && find . -type f | sort)" ] ||
    { echo "         files were written"; return 1; }
}

# compare_case NAME DIR LINUX_RC WINDOWS_RC WANTED_RC RAW_STDOUT: the verdict.
compare_case() {
  local name="$1" dir="$2" lrc="$3" wrc="$4" want="$5" rawout="$6"
  local l="$W/lin/$dir" w="$W/win/$dir" lo="$W/lin/$name" wo="$W/win/$name" problems=() details=()
  [ "$lrc" = "$wrc" ] || problems+=("exit code: Linux $lrc, Windows $wrc")
  [ "$want" = any ] || [ "$lrc" = "$want" ] || problems+=("exit code $lrc, expected $want")
  if [ "$rawout" = 1 ]; then
    cmp -s "$lo.out" "$wo.out" || details+=("standard output: $($py "$here/diffstat.py" "$lo.out" "$wo.out")")
  elif [ "$rawout" = 2 ]; then
    :
  elif ! diff -q <(normalize "$lo.out") <(normalize "$wo.out") >/dev/null; then
    problems+=("standard output differs: $(diff <(normalize "$lo.out") <(normalize "$wo.out") | head -8 | tr '\n' '|')")
  fi
  if ! diff -q <(normalize "$lo.err") <(normalize "$wo.err") >/dev/null; then
    problems+=("messages differ: $(diff <(normalize "$lo.err") <(normalize "$wo.err") | head -8 | tr '\n' '|')")
  fi
  local files f
  files="$( (cd "$l" && find . -type f; cd "$w" && find . -type f) | sort -u)"
  while IFS= read -r f; do
    [ -n "$f" ] || continue
    if [ ! -f "$l/$f" ] || [ ! -f "$w/$f" ]; then
      problems+=("$f written by $([ -f "$l/$f" ] && echo Linux || echo Windows) only")
    elif ! cmp -s "$l/$f" "$w/$f"; then
      details+=("$f: $($py "$here/diffstat.py" "$l/$f" "$w/$f")")
    fi
  done <<<"$files"
  if is_known "$name"; then
    known_seen+=("$name")
    if [ ${#problems[@]} -eq 0 ] && [ ${#details[@]} -eq 0 ]; then
      echo "NOW IDENTICAL  $name (listed in KNOWN_DIVERGENT: remove it)"
      passed=$((passed + 1))
    else
      echo "KNOWN $name"
      local p
      for p in "${problems[@]}" "${details[@]}"; do echo "         $p"; done
    fi
    return
  fi
  if [ ${#problems[@]} -eq 0 ] && [ ${#details[@]} -eq 0 ]; then
    passed=$((passed + 1))
    echo "ok    $name"
  else
    fail "$name"
    local p
    for p in "${problems[@]}" "${details[@]}"; do echo "         $p"; done
  fi
}

# check NAME CONDITION...: a Windows-only expectation (a shell test), reported like a case.
check() {
  local name="$1"
  shift
  if "$@"; then
    passed=$((passed + 1))
    echo "ok    $name"
  else
    fail "$name"
  fi
}

source "$here/cases.sh"

echo "windows: $passed passed, ${#failures[@]} failed, ${#known_seen[@]} known divergent, in $(($(date +%s) - t0)) s"
if [ ${#failures[@]} -gt 0 ]; then
  printf 'windows: FAILED: %s\n' "${failures[@]}"
  exit 1
fi
