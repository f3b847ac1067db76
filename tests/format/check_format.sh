#!/usr/bin/env bash
# Fails, naming the files, when a C or C++ source of the project differs from what clang-format
# makes of it with the project's .clang-format. Usage: check_format.sh SOURCE_DIR CLANG_FORMAT
set -euo pipefail
cd "$1"
if [ -d .git ]; then
    git ls-files -z '*.c' '*.cpp' '*.h' | xargs -0 "$2" --dry-run --Werror
else
    find . -path ./build\* -prune -o \( -name '*.c' -o -name '*.cpp' -o -name '*.h' \) -print0 |
        xargs -0 "$2" --dry-run --Werror
fi
