#!/usr/bin/env bash
# Builds weft-d3d-compile.exe (a Windows program, run under wine) from
# d3d_compile.cpp with MinGW-w64 (Debian: g++-mingw-w64-x86-64-win32).
#   tools/d3d-compile/build.sh <output.exe>
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out="${1:?usage: build.sh <output.exe>}"
mkdir -p "$(dirname "$out")"
cxx=x86_64-w64-mingw32-g++-win32
command -v "$cxx" >/dev/null || cxx=x86_64-w64-mingw32-g++
# Static: the program needs no MinGW runtime DLLs beside it.
"$cxx" -std=c++17 -O2 -Wall -Wextra -Werror -static -o "$out" "$here/d3d_compile.cpp"
