//! The material file: its presets against Table II, its default curves.

use super::*;

pub(super) fn load_material() -> weft_front::Material {
    let root = materials_root();
    let path = root.join("microcylinder/microcylinder.toml");
    let mut db = weft_front::SourceDb::new();
    let mut diags = weft_front::Diagnostics::new();
    match weft_front::load_material(&path, &root, &mut db, &mut diags) {
        Some(m) => m,
        None => panic!(
            "{} does not load:\n{}",
            path.display(),
            diags.render_plain(&db)
        ),
    }
}

pub(super) fn preset_number(values: &[(String, PresetValue)], key: &str) -> f64 {
    match values.iter().find(|(k, _)| k == key) {
        Some((_, PresetValue::Param(ParamValue::Float(x)))) => *x,
        other => panic!("preset value {key}: {other:?}"),
    }
}

pub(super) fn preset_vector(values: &[(String, PresetValue)], key: &str) -> Vec<f64> {
    match values.iter().find(|(k, _)| k == key) {
        Some((_, PresetValue::Param(ParamValue::Vector(v)))) => v.clone(),
        other => panic!("preset value {key}: {other:?}"),
    }
}

pub(super) fn preset_keyword(values: &[(String, PresetValue)], key: &str) -> String {
    match values.iter().find(|(k, _)| k == key) {
        Some((_, PresetValue::Keyword(v))) => v.clone(),
        other => panic!("preset value {key}: {other:?}"),
    }
}

/// Checks one thread set of a preset against Table II; returns the preset's
/// own thread (linear albedo from its sRGB colour) and profile.
pub(super) fn check_preset_thread(
    name: &str,
    values: &[(String, PresetValue)],
    j: u32,
    want: &Thread,
    want_a: f64,
    want_p: &Profile,
) -> (Thread, f64, Profile) {
    let k = |s: &str| format!("thread{j}_{s}");
    let srgb = preset_vector(values, &k("color"));
    let albedo = [0, 1, 2].map(|c| weft_front::samples::srgb_to_linear(srgb[c]));
    for c in 0..3 {
        assert!(
            (albedo[c] - want.albedo[c]).abs() <= 5e-5,
            "{name}: thread{j}_color decodes to {albedo:?}, Table II says {:?}",
            want.albedo
        );
    }
    let th = Thread {
        albedo,
        eta: preset_number(values, &k("ior")),
        kd: preset_number(values, &k("isotropy")),
        gamma_s: preset_number(values, &k("gamma_s")).to_radians(),
        gamma_v: preset_number(values, &k("gamma_v")).to_radians(),
        transmission: Transmission::PerDirection,
    };
    let a = preset_number(values, &k("coverage"));
    for (got, exp, what) in [
        (th.eta, want.eta, "ior"),
        (th.kd, want.kd, "isotropy"),
        (th.gamma_s, want.gamma_s, "gamma_s"),
        (th.gamma_v, want.gamma_v, "gamma_v"),
        (a, want_a, "coverage"),
    ] {
        assert!(
            (got - exp).abs() < 1e-12,
            "{name}: thread{j}_{what} = {got}, Table II says {exp}"
        );
    }
    let count = preset_number(values, &k("offset_count")) as usize;
    let mut all = preset_vector(values, &k("offsets_a"));
    all.extend(preset_vector(values, &k("offsets_b")));
    let offsets = all[..count].to_vec();
    match want_p {
        Profile::List(w) => assert_eq!(&offsets, w, "{name}: offsets of thread set {j}"),
        Profile::Curve(_) => unreachable!(),
    }
    (th, a, Profile::List(offsets))
}

/// The fabrics as the shipped presets define them (after checking them
/// against Table II).
pub(super) fn preset_fabrics(m: &weft_front::Material) -> Vec<Fabric> {
    table_ii()
        .into_iter()
        .map(|(key, want)| {
            let p = m
                .presets
                .iter()
                .find(|p| p.name == key)
                .unwrap_or_else(|| panic!("preset `{key}` missing"));
            assert_eq!(
                preset_keyword(&p.values, "TANGENT_OFFSETS"),
                "list",
                "{key}"
            );
            assert_eq!(preset_keyword(&p.values, "USE_SECOND_PARA"), "on", "{key}");
            let (t1, a1, p1) = check_preset_thread(key, &p.values, 1, &want.t1, want.a1, &want.p1);
            let (t2, a2, p2) = check_preset_thread(key, &p.values, 2, &want.t2, want.a2, &want.p2);
            Fabric {
                name: want.name,
                t1,
                a1,
                p1,
                t2,
                a2,
                p2,
                use2: true,
            }
        })
        .collect()
}

/// The default keyframes of a curve parameter, baked as the toolchain bakes
/// them (then rounded to f32, which is what the uniform holds).
pub(super) fn default_curve(m: &weft_front::Material, name: &str) -> Vec<f64> {
    let p = m.params.iter().find(|p| p.name == name).unwrap();
    assert_eq!(p.samples as usize, CURVE_SAMPLES, "{name}: samples");
    match &p.default {
        ParamValue::Curve(keys) => {
            let span = weft_front::samples::curve_time_range(keys);
            assert_eq!(
                span,
                [0.0, 1.0],
                "{name}: the shader assumes key times 0..1"
            );
            bake(keys)
        }
        other => panic!("{name}: {other:?}"),
    }
}

pub(super) fn bake(keys: &[Keyframe]) -> Vec<f64> {
    weft_front::samples::sample_curve(keys, CURVE_SAMPLES as u32)
        .into_iter()
        .map(|x| x as f32 as f64)
        .collect()
}

pub(super) fn default_fabric(m: &weft_front::Material) -> Fabric {
    let num = |n: &str| match &m.params.iter().find(|p| p.name == n).unwrap().default {
        ParamValue::Float(x) => *x,
        ParamValue::Int(x) => *x as f64,
        ParamValue::Vector(v) => v[0],
        other => panic!("{n}: {other:?}"),
    };
    let color = |n: &str| match &m.params.iter().find(|p| p.name == n).unwrap().default {
        ParamValue::Vector(v) => [0, 1, 2].map(|c| weft_front::samples::srgb_to_linear(v[c])),
        other => panic!("{n}: {other:?}"),
    };
    let th = |j: u32| Thread {
        albedo: color(&format!("thread{j}_color")),
        eta: num(&format!("thread{j}_ior")),
        kd: num(&format!("thread{j}_isotropy")),
        gamma_s: num(&format!("thread{j}_gamma_s")).to_radians(),
        gamma_v: num(&format!("thread{j}_gamma_v")).to_radians(),
        transmission: Transmission::PerDirection,
    };
    Fabric {
        name: "default (linen, curves)",
        t1: th(1),
        a1: num("thread1_coverage"),
        p1: Profile::Curve(default_curve(m, "thread1_curve")),
        t2: th(2),
        a2: num("thread2_coverage"),
        p2: Profile::Curve(default_curve(m, "thread2_curve")),
        use2: true,
    }
}

/// A steeper, asymmetric profile (slopes up to 1.5, i.e. offsets up to 56 deg).
pub(super) fn bumpy_curve() -> Vec<f64> {
    let k = |time, value, slope| Keyframe {
        time,
        value,
        in_slope: slope,
        out_slope: slope,
    };
    bake(&[
        k(0.0, 0.0, 1.5),
        k(0.4, 0.25, 0.0),
        k(0.7, 0.1, -1.0),
        k(1.0, 0.0, 0.2),
    ])
}
