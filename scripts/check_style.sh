#!/usr/bin/env bash
# The habits CI checks before it builds (scripts/test.sh):
#   - every C++ file is formatted as .clang-format says (clang-format --dry-run --Werror);
#   - every Python file passes pyflakes (Debian's pyflakes3): no unused imports, undefined
#     names or placeholder-less f-strings;
#   - no #include runs against the layer order (app -> server -> api -> solver, and the
#     server's floors http -> services -> run -> db -> core) and every header opens with a
#     comment saying what it holds (scripts/check_layers.py; docs/architecture.md);
#   - every reference to a doc's section (docs/X.md "Section") or to a source file by its path
#     resolves (scripts/check_doc_refs.py).
# (The build itself runs with -Werror in CI: SLIPFRONT_WERROR=ON.)
# Fix formatting with: git ls-files '*.cpp' '*.hpp' | xargs clang-format -i
set -euo pipefail
cd "$(dirname "$0")/.."
status=0
mapfile -t cpp < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.cc')
if ! clang-format --dry-run --Werror "${cpp[@]}"; then
  echo "check_style: C++ files not formatted (git ls-files '*.cpp' '*.hpp' | xargs clang-format -i)" >&2
  status=1
fi
mapfile -t py < <(git ls-files '*.py' clients/slipfront-client)
if ! pyflakes3 "${py[@]}"; then
  echo "check_style: pyflakes3 found problems in the Python above" >&2
  status=1
fi
if ! /usr/bin/python3 scripts/check_layers.py; then
  echo "check_style: scripts/check_layers.py found the problems above" >&2
  status=1
fi
if ! /usr/bin/python3 scripts/check_doc_refs.py; then
  echo "check_style: scripts/check_doc_refs.py found the broken references above" >&2
  status=1
fi
[ "$status" = 0 ] && echo "check_style: ${#cpp[@]} C++ files formatted, ${#py[@]} Python files clean"
exit "$status"
