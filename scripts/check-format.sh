#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fails (exit 1) if any tracked C++ file differs from what clang-format makes of it with the
# checked-in .clang-format, and lists those files. Fix with:
#   git ls-files '*.cpp' '*.h' | xargs clang-format -i
# Comment tables that must keep their columns go between "// clang-format off" and "on".
# Also fails if a tracked source file (C++, shell, Python, CMake) lacks its licence line,
# "SPDX-License-Identifier: Apache-2.0", in its first three lines (after a #! line).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang-format >/dev/null; then
  echo "check-format: clang-format is not installed (apt-get install clang-format)" >&2
  exit 1
fi
bad=()
while IFS= read -r f; do
  if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then bad+=("$f"); fi
done < <(git ls-files '*.cpp' '*.h' '*.cc' '*.hpp')
if [ ${#bad[@]} -gt 0 ]; then
  echo "check-format: ${#bad[@]} file(s) are not clang-formatted:" >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
nolicence=()
while IFS= read -r f; do
  if ! head -n 3 "$f" | grep -q 'SPDX-License-Identifier: Apache-2.0'; then nolicence+=("$f"); fi
done < <(git ls-files '*.cpp' '*.h' '*.cc' '*.hpp' '*.sh' '*.py' '*.cmake' '*CMakeLists.txt' \
  .ci/run | grep -v '^tests/data/')
if [ ${#nolicence[@]} -gt 0 ]; then
  echo "check-format: ${#nolicence[@]} file(s) lack the line 'SPDX-License-Identifier: Apache-2.0':" >&2
  printf '  %s\n' "${nolicence[@]}" >&2
  exit 1
fi
echo "check-format: all C++ files are clang-formatted; every source file carries its SPDX line"
