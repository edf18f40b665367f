#!/usr/bin/env python3
"""Fits the Gaussians of the laser fast tier's spectral sensitivity.

The reference (lib/thin_film.wgsl, weft_film_spectral) integrates against the
Wyman-Sloan-Shirley 2013 multi-lobe fit of the CIE 1931 CMFs over 380-780 nm.
The fast tier (weft_film_orders, weft_film_lobe_orders) needs the same CMFs as sums of Gaussians
in wavenumber k = 1/lambda (um^-1), whose cosine transforms are closed-form.
This script fits them (Levenberg-Marquardt on log-amplitudes and log-widths,
amplitude signs fixed) and prints the WGSL constants: weights a*sigma*sqrt(2 pi),
centres mu, widths sigma, and their sums (the sensitivity at OPD = 0).

    python3 materials/laser/fit_cmf.py        # needs numpy; deterministic

tests/physics/laser_film.rs checks the shipped constants against the same target.
"""
import numpy as np


def lobe(lam, mu, s1, s2):
    t = (lam - mu) / np.where(lam < mu, s1, s2)
    return np.exp(-0.5 * t * t)


def wyman(lam):
    x = 1.056 * lobe(lam, 599.8, 37.9, 31.0) + 0.362 * lobe(lam, 442.0, 16.0, 26.7) - 0.065 * lobe(lam, 501.1, 20.4, 26.2)
    y = 0.821 * lobe(lam, 568.8, 46.9, 40.5) + 0.286 * lobe(lam, 530.9, 16.3, 31.1)
    z = 1.217 * lobe(lam, 437.0, 11.8, 36.0) + 0.681 * lobe(lam, 459.0, 26.0, 13.8)
    return np.stack([x, y, z], -1)


K = np.linspace(1 / 0.780, 1 / 0.380, 2000)  # um^-1
LAM = 1000.0 / K  # nm
# CMF per unit wavenumber: d lambda / d k = lambda^2 / 1000 (nm per um^-1).
TARGET = wyman(LAM) * (LAM ** 2 / 1000.0)[:, None]


def unpack(p, signs):
    return [(sg * np.exp(p[3 * i]), p[3 * i + 1], np.exp(p[3 * i + 2])) for i, sg in enumerate(signs)]


def model(p, signs):
    return sum(a * np.exp(-((K - mu) ** 2) / (2 * s * s)) for a, mu, s in unpack(p, signs))


def fit(target, init, signs):
    p = np.array([v for a, mu, s in init for v in (np.log(abs(a)), mu, np.log(s))])
    damping = 1e-2
    cost = lambda q: np.sum((model(q, signs) - target) ** 2)
    for _ in range(4000):
        r = model(p, signs) - target
        jac = np.zeros((len(K), len(p)))
        for j in range(len(p)):
            q = p.copy()
            q[j] += 1e-7
            jac[:, j] = (model(q, signs) - target - r) / 1e-7
        a = jac.T @ jac
        with np.errstate(all="ignore"):
            try:
                step = np.linalg.solve(a + damping * np.diag(np.diag(a) + 1e-9), -jac.T @ r)
            except np.linalg.LinAlgError:
                damping *= 10
                continue
        q = p + step
        if np.all(np.isfinite(q)) and cost(q) < cost(p):
            p, damping = q, max(damping * 0.5, 1e-9)
        else:
            damping *= 4
    rel_rms = np.sqrt(np.mean((model(p, signs) - target) ** 2)) / target.max()
    return unpack(p, signs), rel_rms


STARTS = [
    ([(398, 1.648, 0.1126), (73.4, 2.238, 0.0978), (128.3, 1.519, 0.0711)], [1, 1, -1]),
    ([(300, 1.75, 0.13), (80, 1.88, 0.07), (20, 1.6, 0.05)], [1, 1, 1]),
    ([(60, 2.31, 0.04), (360, 2.2, 0.11)], [1, 1]),
]

lobes = []
for c, (init, signs) in enumerate(STARTS):
    fitted, err = fit(TARGET[:, c], init, signs)
    print(f"{'xyz'[c]}: relative RMS {err:.4f}")
    lobes += fitted
weights = [a * s * np.sqrt(2 * np.pi) for a, mu, s in lobes]
print("weights", ", ".join(f"{w:.6g}" for w in weights))
print("mu     ", ", ".join(f"{mu:.6g}" for a, mu, s in lobes))
print("sigma  ", ", ".join(f"{s:.6g}" for a, mu, s in lobes))
print("at zero", sum(weights[0:3]), sum(weights[3:6]), sum(weights[6:8]))
