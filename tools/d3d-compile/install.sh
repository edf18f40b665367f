#!/usr/bin/env bash
# Fetches the D3D-side compilers tests/hlsl_d3d.rs runs under wine and builds
# the driver that runs them, into target/tools/d3d/ (or $1):
#   bin/dxcompiler.dll, bin/dxil.dll   DXC 1.9, from PyPI slangpy 0.43.1's Windows wheel
#   bin/d3dcompiler_47.dll             FXC (SM 5.1), from PyPI cefpython3 66.1's
#   weft-d3d-compile.exe               built from tools/d3d-compile/d3d_compile.cpp
# Needs python3 with venv, MinGW-w64 (Debian: g++-mingw-w64-x86-64-win32)
# and, to run, wine (Debian: wine64). The wheels (153 MB) are checked against
# the hashes below and cached in <dir>/dl: a second run downloads nothing.
set -euo pipefail
cd "$(dirname "$0")/../.."
dir="${1:-target/tools/d3d}"
mkdir -p "$dir/dl" "$dir/bin"
if [ ! -x "$dir/venv/bin/pip" ]; then
    python3 -m venv "$dir/venv"
fi
cat > "$dir/requirements.txt" <<'REQ'
slangpy==0.43.1 --hash=sha256:3da28207fa1f173c81b22efc1cd02e4804066b975a18749b1a7b09c0708018d6
cefpython3==66.1 --hash=sha256:afe1bcde78cbd3790370f4a51cbca37de8bff761de0452f8b8a3b22971bed82a
REQ
"$dir/venv/bin/pip" download --quiet --disable-pip-version-check --no-deps \
    --only-binary=:all: --platform win_amd64 --python-version 3.11 \
    --require-hashes -r "$dir/requirements.txt" --dest "$dir/dl"
"$dir/venv/bin/python" - "$dir" <<'PY'
import glob, sys, zipfile
d = sys.argv[1]
for wheel, names in [
    ("slangpy-0.43.1-*win_amd64.whl", ["slangpy/dxcompiler.dll", "slangpy/dxil.dll"]),
    ("cefpython3-66.1-*win_amd64.whl", ["cefpython3/d3dcompiler_47.dll"]),
]:
    with zipfile.ZipFile(glob.glob(f"{d}/dl/{wheel}")[0]) as z:
        for name in names:
            with open(f"{d}/bin/{name.split('/')[-1]}", "wb") as out:
                out.write(z.read(name))
PY
tools/d3d-compile/build.sh "$dir/weft-d3d-compile.exe"
