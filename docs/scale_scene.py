#!/usr/bin/env python3
"""Writes a large scene for timing the scene limits (docs/scaling.md, "Scene limits").

    python3 docs/scale_scene.py SCENE N MODE OUT_DIR

N instances, cycling through SCENE's instances that are not `tier = "auto"`
(auto tiers are measured on lavapipe, which is not what is timed here), each
at its own position, into OUT_DIR/scale_<MODE>_<N>.scene.toml (materials: the
root beside SCENE). MODE:

  copies    the same instances repeated: they share the shaders of SCENE's
  distinct  each instance also gets its own value of a parameter its shader
            reads, so each needs its own specialised shader
  cap       N instances needing 256 distinct shaders (the most the build takes)
"""
import os
import sys
import tomllib

src, n, mode, out = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
assert mode in ("copies", "distinct", "cap"), mode
scene = tomllib.load(open(src, "rb"))
templates = [i for i in scene["instances"] if i.get("tier") != "auto"]
# A parameter each material's shader reads (scene/fitting_room's materials).
vary = {"satin": "roughness", "velvet": "smoothness", "gauze": "roughness",
        "microcylinder": "thread1_coverage", "standard": "roughness"}
name = f"scale_{mode}_{n}"
root = os.path.relpath(
    os.path.join(os.path.dirname(os.path.abspath(src)), "..", "materials"), out)


def toml(v):
    if isinstance(v, str):
        return '"' + v + '"'
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, list):
        return "[" + ", ".join(toml(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{k} = {toml(x)}" for k, x in v.items()) + " }"
    return repr(v)


lines = ["[scene]", f'name = "{name}"', f'materials = "{root}"',
         'vertex_inputs = ["position", "normal", "tangent", "uv0"]', ""]
for k in range(n):
    j = k % 256 if mode == "cap" else k
    t = dict(templates[j % len(templates)])
    t["name"] = f"i{k}"
    t["translation"] = [float(k % 32), float(k // 32), 0.0]
    if mode != "copies":
        params = dict(t.get("params", {}))
        params[vary[t["material"]]] = 0.1 + 0.8 * j / (256 if mode == "cap" else n)
        t["params"] = params
    lines.append("[[instances]]")
    lines += [f"{key} = {toml(v)}" for key, v in t.items()]
    lines.append("")
with open(os.path.join(out, f"{name}.scene.toml"), "w") as f:
    f.write("\n".join(lines))
