#!/usr/bin/env python3
"""What folding the frame's light (and the environment's mip count) into the
scene shaders would add to scene specialisation on AMD's compiler
(docs/performance.md, "Scene specialisation on AMD's compiler").

    python3 docs/frame_constant_probe.py [--mip-count N]

Engine interface v1 makes the main light and the environment run-time inputs
(`weft_frame.light_direction`, `.light_color`, `.params.x`), so weft's scene
build does not fold them. This probe measures what it would gain if a scene
could declare them fixed: in a temporary copy of `generated/`, each scene
shader's WGSL gets the scene metadata's `light` (and, with --mip-count, that
mip count) as literals, is compiled to SPIR-V again with naga's CLI
(`cargo install naga-cli --version 30.0.1`), and the whole library is costed
by `cargo xtask bench gpu-model` (Mesa RADV, no GPU) with WEFT_ROOT at the
copy. Printed: per family, the median fragment-instruction reduction per
scene shader and pass against the committed generic figures
(generated/reports/gpu-model.json), as weft-gpu-stats's test computes it,
and the rows below the median. The checkout is not modified.
"""
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def literal(v):
    return "vec4<f32>(%s, 0f)" % ", ".join(f"{float(x)!r}f" for x in v)


def fold(scene_dir, mip_count):
    """Rewrites the scene's shaders in place; returns how many changed."""
    name = os.path.basename(scene_dir)
    light = json.load(open(os.path.join(scene_dir, f"{name}.scene.json")))["light"]
    changed = 0
    for wgsl in sorted(glob.glob(os.path.join(scene_dir, "*.wgsl"))):
        src = open(wgsl).read()
        out = re.sub(r"weft_frame\.light_direction\b", literal(light["direction"]), src)
        out = re.sub(r"weft_frame\.light_color\b", literal(light["color"]), out)
        if mip_count is not None:
            out = re.sub(r"weft_frame\.params\.x\b", f"{float(mip_count)!r}f", out)
        if out == src:
            continue
        open(wgsl, "w").write(out)
        subprocess.run(["naga", wgsl, wgsl[: -len(".wgsl")] + ".spv"], check=True)
        changed += 1
    return changed


def fragment_instructions(stats):
    """(scene, shader, pass) -> fragment-stage ISA instructions, per family."""
    out = {}
    for family in stats:
        figures = out.setdefault(family["family"], {})
        for p in family["pipelines"]:
            src = p["source"]
            if src["kind"] != "scene":
                continue
            for stage in p["stages"]:
                if stage["stage"] == "fragment":
                    n = next(s["value"] for s in stage["statistics"] if s["name"] == "Instructions")
                    figures[(src["scene"], src["shader"], p["pass"])] = n
    return out


def main():
    mip_count = None
    if sys.argv[1:2] == ["--mip-count"]:
        mip_count = int(sys.argv[2])
    elif len(sys.argv) > 1:
        sys.exit(__doc__)
    committed = json.load(open(os.path.join(ROOT, "generated/reports/gpu-model.json")))
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copytree(os.path.join(ROOT, "generated"), os.path.join(tmp, "generated"))
        changed = sum(fold(d, mip_count) for d in sorted(glob.glob(os.path.join(tmp, "generated/scenes/*"))) if os.path.isdir(d))
        print(f"{changed} scene shader files rewritten")
        stats_path = os.path.join(tmp, "stats.json")
        subprocess.run(["cargo", "xtask", "bench", "gpu-model", "--json", stats_path],
                       cwd=ROOT, env={**os.environ, "WEFT_ROOT": tmp}, check=True,
                       stdout=subprocess.DEVNULL)
        folded = fragment_instructions(json.load(open(stats_path)))
    for family in committed["families"]:
        rows = []
        for s in family["scene_shaders"]:
            key = (s["scene"], s["shader"], s["pass"])
            generic = s["generic"]["instructions"]
            now, probe = s["specialised"]["instructions"], folded[family["family"]][key]
            rows.append((100 * (1 - probe / generic), 100 * (1 - now / generic), key, now, probe))
        rows.sort()
        median = lambda xs: sorted(xs)[len(xs) // 2]
        print(f"{family['family']}: median reduction per scene shader × pass "
              f"{median([r[1] for r in rows]):.1f} % → {median([r[0] for r in rows]):.1f} % "
              f"over {len(rows)} pipelines")
        for probe_pct, now_pct, key, now, probe in rows[: len(rows) // 2 + 1]:
            print(f"  {' '.join(key)}: {now} → {probe} instructions ({now_pct:.1f} % → {probe_pct:.1f} %)")


if __name__ == "__main__":
    main()
