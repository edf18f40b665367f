//! A core-PBR glTF material on a flat probe against the glTF 2.0
//! specification's BRDF (Appendix B), a module of the `scenes` test binary.
//!
//! The material goes through weft's glTF mapping (`map_material`: factors
//! sRGB-encoded into standard's parameters) and is drawn by standard's
//! `reference` tier on the stability probe's flat tiles (N, V, L exact per
//! tile), lit by the main light alone (black environment, no ambient). The
//! reference is written here in f64 from the specification:
//!
//! - `material = mix(dielectric_brdf, metal_brdf, metallic)`;
//! - `metal_brdf = specular_brdf(α) · (baseColor + (1 − baseColor)(1 − |V·H|)⁵)`;
//! - `dielectric_brdf = mix(baseColor / π, specular_brdf(α), 0.04 + 0.96 (1 − |V·H|)⁵)`;
//! - `specular_brdf = V · D`, `D` the GGX distribution, `α = roughness²`,
//!   `V` the Smith joint masking-shadowing: the specification writes the
//!   separable form `G₁(L) G₁(V) / (4 |N·L| |N·V|)`; the Khronos sample
//!   renderer (what the mapping's conventions follow) the height-correlated
//!   one `0.5 / (N·L √(N·V²(1 − α²) + α²) + N·V √(N·L²(1 − α²) + α²))`.
//!
//! Metals (no diffuse lobe) must match the sample renderer's form within
//! f32 rounding (1e-4 relative): every factor of the mapping and of the
//! specular lobe is checked there. Dielectrics differ by weft's documented
//! choice of direct diffuse weight (`1 − E(n·v)`, the split-sum albedo,
//! where glTF takes `1 − F(v·h)`: materials/standard/README.md): with
//! glTF's specular lobe taken away, what is left must be Lambert times one
//! weight per view direction, the same for every light, at most 1 − F0 and
//! 1 − F0 at normal view. Both tables are printed (`--nocapture`) and
//! quoted in docs/gltf.md.

use std::f64::consts::PI;
use weft_render::probe::{GeometricCase, Probe};
use weft_render::{CubeLevel, EnvironmentMaps, Gpu, Luts, Material, Renderer};
use weft_tests::repo;

/// No environment light: every mip black, no SH.
pub(super) fn black_environment() -> EnvironmentMaps {
    let mips: Vec<CubeLevel> = [4u32, 2, 1]
        .iter()
        .map(|&size| CubeLevel {
            size,
            data: vec![[0.0; 3]; (size * size * 6) as usize],
        })
        .collect();
    EnvironmentMaps {
        mip_roughness: vec![0.0, 0.5, 1.0],
        mips,
        sh: [[0.0; 3]; 9],
    }
}

pub(super) type V3 = [f64; 3];

/// A renderer for the flat probe: lavapipe, the committed LUTs, no
/// environment light.
pub(super) fn flat_probe_renderer(generated: &std::path::Path) -> Renderer {
    let luts = Luts::load_dir(generated).unwrap();
    let gpu = Gpu::new().unwrap_or_else(|e| {
        panic!("the flat-probe check needs a Vulkan adapter (install mesa-vulkan-drivers for lavapipe): {e}")
    });
    Renderer::new(gpu, &black_environment(), &luts).unwrap()
}

/// One flat tile (normal +Z, tangent +X) per (view, light) pair, unit
/// light radiance, one pixel each.
pub(super) fn flat_probe(geometry: &[(V3, V3)]) -> Probe {
    let cases: Vec<GeometricCase> = geometry
        .iter()
        .enumerate()
        .map(|(i, (v, l))| GeometricCase {
            name: format!("case {i}"),
            normal: [0.0, 0.0, 1.0],
            tangent: [1.0, 0.0, 0.0, 1.0],
            view: v.map(|x| x as f32),
            light: l.map(|x| x as f32),
        })
        .collect();
    Probe::new(cases, [1.0; 3], 1, 16)
}

pub(super) fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(super) fn normalize(a: V3) -> V3 {
    let l = dot(a, a).sqrt();
    a.map(|x| x / l)
}

/// A unit direction at polar angle `theta` (degrees) from +Z, azimuth `phi`.
pub(super) fn dir(theta: f64, phi: f64) -> V3 {
    let (t, p) = (theta.to_radians(), phi.to_radians());
    [t.sin() * p.cos(), t.sin() * p.sin(), t.cos()]
}

/// Which Smith term the reference uses.
#[derive(Clone, Copy)]
enum Smith {
    /// The specification's Appendix B text.
    Separable,
    /// The Khronos glTF Sample Renderer's.
    HeightCorrelated,
}

/// glTF 2.0 Appendix B's BRDF × n·l for unit radiance, per channel.
fn gltf_brdf(base: V3, metallic: f64, roughness: f64, n: V3, v: V3, l: V3, smith: Smith) -> V3 {
    let h = normalize([v[0] + l[0], v[1] + l[1], v[2] + l[2]]);
    let (nl, nv, nh, vh) = (dot(n, l), dot(n, v), dot(n, h), dot(v, h).abs());
    if nl <= 0.0 || nv <= 0.0 {
        return [0.0; 3];
    }
    let a2 = (roughness * roughness).powi(2);
    let d = if nh > 0.0 {
        a2 / (PI * (nh * nh * (a2 - 1.0) + 1.0).powi(2))
    } else {
        0.0
    };
    let vis = match smith {
        Smith::Separable => {
            let g1 = |x: f64| 2.0 * x / (x + (a2 + (1.0 - a2) * x * x).sqrt());
            g1(nl) * g1(nv) / (4.0 * nl * nv)
        }
        Smith::HeightCorrelated => {
            0.5 / (nl * (nv * nv * (1.0 - a2) + a2).sqrt()
                + nv * (nl * nl * (1.0 - a2) + a2).sqrt())
        }
    };
    let specular = vis * d;
    let schlick = (1.0 - vh).powi(5);
    let fr = 0.04 + 0.96 * schlick;
    std::array::from_fn(|c| {
        let metal = specular * (base[c] + (1.0 - base[c]) * schlick);
        let dielectric = base[c] / PI * (1.0 - fr) + specular * fr;
        ((1.0 - metallic) * dielectric + metallic * metal) * nl
    })
}

/// A one-material glTF with core factors, mapped by weft's glTF front end;
/// its parameters set on standard's metadata as the scene would set them.
fn mapped_material(
    generated: &std::path::Path,
    base: V3,
    metallic: f64,
    roughness: f64,
) -> Material {
    let json = serde_json::json!({
        "asset": { "version": "2.0" },
        "materials": [ { "pbrMetallicRoughness": {
            "baseColorFactor": [base[0], base[1], base[2], 1.0],
            "metallicFactor": metallic, "roughnessFactor": roughness } } ]
    });
    material_from(generated, &json, "standard", "reference")
}

/// Material 0 of a glTF (JSON) mapped by weft's glTF front end onto
/// `expected` (its tier `tier`), with the mapping's values set on the
/// material's metadata as a scene sets them.
pub(super) fn material_from(
    generated: &std::path::Path,
    json: &serde_json::Value,
    expected: &str,
    tier: &str,
) -> Material {
    let mut warnings = Vec::new();
    let file = weft_front::gltf::GltfFile::from_bytes(
        std::path::Path::new("probe.gltf"),
        None,
        serde_json::to_vec(json).unwrap(),
        &mut warnings,
    )
    .unwrap();
    let mapping = weft_front::gltf::materials::map_material(&file, Some(0), "probe.gltf").unwrap();
    assert_eq!(mapping.material, expected, "{json}");
    let mut material =
        Material::load(generated.join(format!("{expected}/{expected}.meta.json"))).unwrap();
    material
        .set_tier(mapping.tier.as_deref().unwrap_or(tier))
        .unwrap();
    assert_eq!(material.tier(), tier);
    for (name, literal) in &mapping.params {
        let value: toml::Value =
            toml::from_str::<toml::Table>(&format!("v = {literal}")).unwrap()["v"].clone();
        match value {
            toml::Value::Float(x) => material.set(name, x).unwrap(),
            toml::Value::Array(a) => {
                let c: Vec<f64> = a.iter().map(|x| x.as_float().unwrap()).collect();
                material.set(name, [c[0], c[1], c[2], c[3]]).unwrap()
            }
            other => panic!("{name} = {other}: not a factor"),
        }
    }
    material
}

#[test]
fn a_core_pbr_gltf_renders_the_gltf_specifications_brdf() {
    let _gpu = weft_tests::gpu_serial();
    let generated = repo().join("generated");
    let mut renderer = flat_probe_renderer(&generated);
    let n: V3 = [0.0, 0.0, 1.0];
    let mut geometry = Vec::new();
    for tv in [0.0, 30.0, 60.0, 80.0] {
        for tl in [0.0, 30.0, 60.0, 80.0] {
            for phi in [0.0, 90.0, 180.0] {
                geometry.push((dir(tv, 0.0), dir(tl, phi)));
            }
        }
    }
    let probe = flat_probe(&geometry);
    let base: V3 = [0.8, 0.3, 0.1];
    println!(
        "| metallic | roughness | worst relative vs sample renderer (height-correlated) | vs specification text (separable) |"
    );
    println!("|---|---|---|---|");
    let mut failures = Vec::new();
    let mut weights = Vec::new();
    for metallic in [1.0, 0.0] {
        for roughness in [0.2, 0.5, 0.9] {
            let material = mapped_material(&generated, base, metallic, roughness);
            let prepared = renderer
                .prepare(&material, &probe.render_options())
                .unwrap();
            let tiles = probe.evaluate(&mut renderer, &prepared).unwrap();
            let (mut worst_hc, mut worst_sep) = (0.0f64, 0.0f64);
            // Dielectrics: per view angle, the direct diffuse weight each
            // light direction shows (what is left after glTF's specular,
            // over Lambert's), and glTF's own 1 − F(v·h) there.
            let mut by_view: Vec<(f64, Vec<f64>, Vec<f64>)> = Vec::new();
            for ((v, l), px) in geometry.iter().zip(&tiles) {
                let got = px[0].map(f64::from);
                let hc = gltf_brdf(
                    base,
                    metallic,
                    roughness,
                    n,
                    *v,
                    *l,
                    Smith::HeightCorrelated,
                );
                let sep = gltf_brdf(base, metallic, roughness, n, *v, *l, Smith::Separable);
                for c in 0..3 {
                    // Relative to the larger of the value and 1e-3 (a dark
                    // channel's absolute error counts as such).
                    let rel = |want: f64| (got[c] - want).abs() / want.abs().max(1e-3);
                    worst_hc = worst_hc.max(rel(hc[c]));
                    worst_sep = worst_sep.max(rel(sep[c]));
                }
                if metallic == 0.0 {
                    let specular_only =
                        gltf_brdf([0.0; 3], 0.0, roughness, n, *v, *l, Smith::HeightCorrelated);
                    let nl = dot(n, *l);
                    let lambert = base[0] / PI * nl;
                    // The red channel (albedo 0.8), where the diffuse lobe
                    // is not swamped by a sharp highlight (f32 rounding of
                    // the highlight would show as weight).
                    if specular_only[0] > lambert {
                        continue;
                    }
                    let weight = vec![(got[0] - specular_only[0]) / lambert];
                    let h = normalize([v[0] + l[0], v[1] + l[1], v[2] + l[2]]);
                    let gltf_weight = 1.0 - (0.04 + 0.96 * (1.0 - dot(*v, h)).powi(5));
                    let nv = dot(n, *v);
                    match by_view.iter_mut().find(|(x, _, _)| (*x - nv).abs() < 1e-9) {
                        Some((_, w, g)) => {
                            w.extend(weight);
                            g.push(gltf_weight);
                        }
                        None => by_view.push((nv, weight, vec![gltf_weight])),
                    }
                }
            }
            println!("| {metallic} | {roughness} | {worst_hc:.2e} | {worst_sep:.2e} |");
            // Metals (no diffuse lobe): exactly the sample renderer's BRDF.
            if metallic == 1.0 && worst_hc > 1e-4 {
                failures.push(format!(
                    "metal, roughness {roughness}: {worst_hc:.3e} from the sample renderer's BRDF"
                ));
            }
            // Dielectrics: glTF's specular lobe plus Lambert times a weight
            // that depends on the view alone (weft's 1 − E(n·v)), within
            // (0, 1], and 1 − F0 at normal view on a smooth surface (a
            // rough one's single-scattering albedo is below F0 there).
            for (nv, w, g) in &by_view {
                let (lo, hi) = w
                    .iter()
                    .fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
                let (glo, ghi) = g
                    .iter()
                    .fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
                weights.push(format!(
                    "| {roughness} | {nv:.3} | {:.3} | {glo:.3} – {ghi:.3} |",
                    (lo + hi) / 2.0
                ));
                if hi - lo > 2e-3 || hi > 1.0 || lo < 0.4 {
                    failures.push(format!(
                        "dielectric, roughness {roughness}, n·v {nv:.3}: diffuse weights {lo:.4}–{hi:.4} (one view-only weight in (0, 1] expected)"
                    ));
                }
                if *nv > 0.999 && roughness < 0.3 && (hi - 0.96).abs() > 0.005 {
                    failures.push(format!("dielectric, roughness {roughness}: weight {hi:.4} at normal view, not 1 − F0"));
                }
            }
        }
    }
    println!(
        "\n| roughness | n·v | weft's direct diffuse weight (1 − E(n·v)) | glTF's 1 − F(v·h) over the light directions checked (those without a highlight) |"
    );
    println!("|---|---|---|---|");
    for w in &weights {
        println!("{w}");
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The Khronos sample renderer's sheen lobe (Estevez and Kulla 2017's
/// Charlie distribution and its fitted visibility), for α = sheenRoughness².
fn charlie_sheen(sheen_roughness: f64, nh: f64, nv: f64, nl: f64) -> f64 {
    let alpha = (sheen_roughness * sheen_roughness).max(1e-6);
    let inv = 1.0 / alpha;
    let d = (2.0 + inv) * (1.0 - nh * nh).max(0.0).powf(inv * 0.5) / (2.0 * PI);
    let helper = |x: f64| {
        let t = (1.0 - alpha) * (1.0 - alpha);
        let mix = |a: f64, b: f64| a + (b - a) * t;
        mix(21.5473, 25.3245) / (1.0 + mix(3.82987, 3.32435) * x.powf(mix(0.19823, 0.16801)))
            + mix(-1.97760, -1.27393) * x
            + mix(-4.32054, -4.85967)
    };
    let lambda = |c: f64| {
        if c.abs() < 0.5 {
            helper(c).exp()
        } else {
            (2.0 * helper(0.5) - helper(1.0 - c)).exp()
        }
    };
    let v = (1.0 / ((1.0 + lambda(nv) + lambda(nl)) * 4.0 * nv * nl)).clamp(0.0, 1.0);
    d * v
}

/// The sheen lobe's directional albedo E(μ) = ∫ f_sheen cos θ_l dω_l, in
/// f64 by the midpoint rule (what the sample renderer bakes into a table).
fn sheen_albedo(mu: f64, sheen_roughness: f64) -> f64 {
    let v: V3 = [(1.0 - mu * mu).max(0.0).sqrt(), 0.0, mu];
    let (nt, np) = (256, 128);
    let mut sum = 0.0;
    for i in 0..nt {
        let theta = (i as f64 + 0.5) / nt as f64 * PI / 2.0;
        for j in 0..np {
            // φ over [0, π]: the lobe is symmetric about the plane of v.
            let phi = (j as f64 + 0.5) / np as f64 * PI;
            let l = [
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            ];
            let h = normalize([v[0] + l[0], v[1] + l[1], v[2] + l[2]]);
            sum += charlie_sheen(sheen_roughness, h[2], mu, l[2]) * l[2] * theta.sin();
        }
    }
    2.0 * sum * (PI / 2.0 / nt as f64) * (PI / np as f64)
}

/// A `KHR_materials_sheen` glTF through the mapping (velvet `reference`)
/// against the sample renderer's sheen model: with a black base, the sheen
/// lobe alone must match (1e-3); with a coloured base, the base is Lambert
/// scaled by min(1 − max(C) E(n·v), 1 − max(C) E(n·l)) against that same
/// model with glTF's base reduced to its diffuse lobe (the GGX base lobe is
/// a declared loss); both differences are printed and quoted in docs/gltf.md.
#[test]
fn a_sheen_gltf_renders_the_sample_renderers_sheen() {
    let _gpu = weft_tests::gpu_serial();
    let generated = repo().join("generated");
    let mut renderer = flat_probe_renderer(&generated);
    let n: V3 = [0.0, 0.0, 1.0];
    let mut geometry = Vec::new();
    for tv in [0.0, 30.0, 60.0, 75.0] {
        for tl in [0.0, 30.0, 60.0, 75.0] {
            for phi in [0.0, 90.0, 180.0] {
                geometry.push((dir(tv, 0.0), dir(tl, phi)));
            }
        }
    }
    let probe = flat_probe(&geometry);
    let sheen: V3 = [0.55, 0.22, 0.3];
    let mut failures = Vec::new();
    println!(
        "| base colour | sheenRoughness | worst relative vs the sample renderer (base: Lambert) | the lost GGX base lobe: worst difference over the peak radiance |"
    );
    println!("|---|---|---|---|");
    for base in [[0.0; 3], [0.5, 0.2, 0.3]] {
        for r in [0.35, 0.6, 0.9] {
            let json = serde_json::json!({
                "asset": { "version": "2.0" },
                "extensionsUsed": ["KHR_materials_sheen"],
                "materials": [ {
                    "pbrMetallicRoughness": { "baseColorFactor": [base[0], base[1], base[2], 1.0],
                        "metallicFactor": 0.0, "roughnessFactor": 0.5 },
                    "extensions": { "KHR_materials_sheen": {
                        "sheenColorFactor": sheen, "sheenRoughnessFactor": r } } } ]
            });
            let material = material_from(&generated, &json, "velvet", "reference");
            let prepared = renderer
                .prepare(&material, &probe.render_options())
                .unwrap();
            let tiles = probe.evaluate(&mut renderer, &prepared).unwrap();
            let c_max = sheen.iter().fold(0.0f64, |a, &b| a.max(b));
            let (mut worst, mut worst_whole, mut peak) = (0.0f64, 0.0f64, 0.0f64);
            for ((v, l), px) in geometry.iter().zip(&tiles) {
                let got = px[0].map(f64::from);
                let (nv, nl) = (dot(n, *v), dot(n, *l));
                let h = normalize([v[0] + l[0], v[1] + l[1], v[2] + l[2]]);
                let lobe = charlie_sheen(r, h[2], nv, nl);
                let scaling =
                    (1.0 - c_max * sheen_albedo(nv, r)).min(1.0 - c_max * sheen_albedo(nl, r));
                let whole_base = gltf_brdf(base, 0.0, 0.5, n, *v, *l, Smith::HeightCorrelated);
                for c in 0..3 {
                    let want = (sheen[c] * lobe + scaling * base[c] / PI) * nl;
                    let want_whole = sheen[c] * lobe * nl + scaling * whole_base[c];
                    let rel = |w: f64| (got[c] - w).abs() / w.abs().max(1e-3);
                    worst = worst.max(rel(want));
                    worst_whole = worst_whole.max((got[c] - want_whole).abs());
                    peak = peak.max(want_whole);
                }
            }
            println!(
                "| {base:?} | {r} | {worst:.2e} | {:.2e} |",
                worst_whole / peak
            );
            let bound = if base == [0.0; 3] { 1e-3 } else { 0.02 };
            if worst > bound {
                failures.push(format!(
                    "base {base:?}, sheenRoughness {r}: {worst:.3e} > {bound}"
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
