#!/usr/bin/env python3
"""A second Mesa RADV beside the system's, to cost weft's shaders with
another release of AMD's compiler (docs/performance.md, "On another Mesa").

    python3 docs/other_mesa.py DIR [--suite bookworm-backports]

Downloads Debian's `mesa-vulkan-drivers` of SUITE and the `libdrm2` and
`libdrm-amdgpu1` it needs from deb.debian.org, unpacks them under DIR
(nothing is installed; the system's Mesa stays as it is), writes an ICD
manifest pointing at the unpacked driver and prints the environment that
makes weft use it, e.g.

    XDG_CONFIG_HOME=DIR/icd LD_LIBRARY_PATH=DIR/root/usr/lib/x86_64-linux-gnu \\
        cargo xtask bench gpu-model

(weft-gpu-stats looks for RADV's manifest in $XDG_CONFIG_HOME/vulkan/icd.d
first, as the Vulkan loader does), and VK_ICD_FILENAMES for its lavapipe,
to render with it too. Needs curl and dpkg-deb.
"""
import argparse
import json
import lzma
import os
import subprocess
import urllib.request

MIRROR = "http://deb.debian.org/debian"
PACKAGES = ["mesa-vulkan-drivers", "libdrm2", "libdrm-amdgpu1"]
LIBDIR = "usr/lib/x86_64-linux-gnu"


def index(suite):
    url = f"{MIRROR}/dists/{suite}/main/binary-amd64/Packages.xz"
    with urllib.request.urlopen(url, timeout=120) as r:
        text = lzma.decompress(r.read()).decode("utf-8", "replace")
    found = {}
    for stanza in text.split("\n\n"):
        fields = dict(
            line.split(": ", 1) for line in stanza.splitlines() if ": " in line and not line.startswith(" ")
        )
        name = fields.get("Package")
        if name in PACKAGES and name not in found:
            found[name] = (fields["Version"], fields["Filename"])
    missing = [p for p in PACKAGES if p not in found]
    if missing:
        raise SystemExit(f"{suite} has no {', '.join(missing)}")
    return found


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dir")
    ap.add_argument("--suite", default="bookworm-backports")
    args = ap.parse_args()
    out = os.path.abspath(args.dir)
    root = os.path.join(out, "root")
    os.makedirs(root, exist_ok=True)
    for name, (version, filename) in index(args.suite).items():
        deb = os.path.join(out, os.path.basename(filename))
        if not os.path.exists(deb):
            subprocess.run(["curl", "-sSf", "-o", deb, f"{MIRROR}/{filename}"], check=True)
        subprocess.run(["dpkg-deb", "-x", deb, root], check=True)
        print(f"{name} {version}")
    icd_dir = os.path.join(out, "icd", "vulkan", "icd.d")
    os.makedirs(icd_dir, exist_ok=True)
    # RADV where weft-gpu-stats looks first; lavapipe apart, so that the
    # loader does not list it beside the system's own.
    manifest(root, "radeon", os.path.join(icd_dir, "radeon_icd.x86_64.json"))
    lavapipe = os.path.join(out, "lvp_icd.x86_64.json")
    manifest(root, "lvp", lavapipe)
    print(f"XDG_CONFIG_HOME={out}/icd LD_LIBRARY_PATH={root}/{LIBDIR}")
    print(f"rendering on its lavapipe as well: VK_ICD_FILENAMES={lavapipe}")


def manifest(root, driver, path):
    """The package's ICD manifest for `driver`, its library by absolute path."""
    with open(os.path.join(root, f"usr/share/vulkan/icd.d/{driver}_icd.json")) as f:
        data = json.load(f)
    data["ICD"]["library_path"] = os.path.join(root, LIBDIR, f"libvulkan_{driver}.so")
    with open(path, "w") as f:
        json.dump(data, f, indent=2)


if __name__ == "__main__":
    main()
