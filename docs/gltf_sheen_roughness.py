#!/usr/bin/env python3
"""What the sheen-roughness convention changes (docs/gltf.md).

KHR_materials_sheen and the Khronos glTF Sample Renderer take Charlie's
alpha = sheenRoughness^2; weft's velvet takes alpha = 1 - smoothness. This
script evaluates the Charlie sheen lobe (Conty Estevez & Kulla 2017: the
distribution and the fitted Smith Lambda, coefficients as in the
KHR_materials_sheen specification) written here from the paper, and
prints the directional albedo E(n.v) with alpha = r^2 against alpha = r
for a few sheenRoughness values r. Pure Python: python3 docs/gltf_sheen_roughness.py
"""
import math

P0 = (25.3245, 3.32435, 0.16801, -1.27393, -4.85967)
P1 = (21.5473, 3.82987, 0.19823, -1.97760, -4.32054)


def d_charlie(alpha, cos_h):
    sin2 = max(0.0, 1.0 - cos_h * cos_h)
    return (2.0 + 1.0 / alpha) * sin2 ** (0.5 / alpha) / (2.0 * math.pi)


def l_fit(x, alpha):
    t = (1.0 - alpha) ** 2
    a, b, c, d, e = ((1 - t) * p + t * q for p, q in zip(P0, P1))
    return a / (1.0 + b * x ** c) + d * x + e


def lam(cos_t, alpha):
    if cos_t < 0.5:
        return math.exp(l_fit(cos_t, alpha))
    return math.exp(2.0 * l_fit(0.5, alpha) - l_fit(1.0 - cos_t, alpha))


def albedo(alpha, nv, steps=96):
    """E(n.v) = integral of D V (n.l) over the hemisphere (white sheen)."""
    v = (math.sqrt(1.0 - nv * nv), 0.0, nv)
    total = 0.0
    for i in range(steps):
        ct = (i + 0.5) / steps  # cos theta_l, uniform: d(omega) = d(cos) d(phi)
        st = math.sqrt(1.0 - ct * ct)
        for j in range(2 * steps):
            phi = (j + 0.5) / (2 * steps) * 2.0 * math.pi
            l = (st * math.cos(phi), st * math.sin(phi), ct)
            h = [a + b for a, b in zip(v, l)]
            n = math.sqrt(sum(x * x for x in h))
            ch = h[2] / n
            vis = 1.0 / ((1.0 + lam(nv, alpha) + lam(ct, alpha)) * 4.0 * nv * ct)
            total += d_charlie(alpha, ch) * vis * ct
    return total * (1.0 / steps) * (2.0 * math.pi / (2 * steps))


def main():
    print("| sheenRoughness r | n.v | E, alpha = r^2 (Khronos, weft's mapping) | E, alpha = r | difference |")
    print("|--:|--:|--:|--:|--:|")
    for r in (0.3, 0.5, 0.7, 0.9):
        for nv in (0.9, 0.5, 0.2):
            a = albedo(max(r * r, 0.07), nv)
            b = albedo(max(r, 0.07), nv)
            print(f"| {r} | {nv} | {a:.3f} | {b:.3f} | {b - a:+.3f} |")


if __name__ == "__main__":
    main()
