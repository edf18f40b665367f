//! Direction pairs, and the compute shader that evaluates the WGSL tiers
//! on lavapipe for them.

use super::*;

pub(super) struct Rng(pub(super) u64);
impl Rng {
    pub(super) fn next(&mut self) -> f64 {
        // xorshift64*
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A direction in the local frame with cos(polar) in [cmin, cmax].
pub(super) fn local_dir(rng: &mut Rng, cmin: f64, cmax: f64) -> V3 {
    let c = cmin + (cmax - cmin) * rng.next();
    let s = (1.0 - c * c).sqrt();
    let phi = 2.0 * PI * rng.next();
    [s * phi.cos(), s * phi.sin(), c]
}

pub(super) fn to_world(t: V3, b: V3, n: V3, d: V3) -> V3 {
    add(add(scale(t, d[0]), scale(b, d[1])), scale(n, d[2]))
}

pub(super) fn round_f32(v: V3) -> V3 {
    v.map(|x| x as f32 as f64)
}

/// Two frames: axis-aligned, and a tilted one (tests nothing assumes n = z).
pub(super) fn frames() -> Vec<(V3, V3, V3)> {
    let n = norm([0.3, -0.5, 0.81]);
    let t = norm(sub([1.0, 0.2, 0.0], scale(n, dot([1.0, 0.2, 0.0], n))));
    let b = cross(n, t);
    vec![
        ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
        (t, b, n),
    ]
}

/// Direction pairs (world, rounded to f32): random pairs and near-mirror pairs.
pub(super) fn direction_pairs(seed: u64, t: V3, b: V3, n: V3) -> Vec<(V3, V3)> {
    let mut rng = Rng(seed);
    let mut out = Vec::new();
    for k in 0..96 {
        let wi = local_dir(&mut rng, 0.03, 0.995);
        let wr = if k % 3 == 0 {
            // Near the mirror direction, where the surface lobes peak.
            let m = [-wi[0], -wi[1], wi[2]];
            norm(add(m, scale(local_dir(&mut rng, -1.0, 1.0), 0.15)))
        } else {
            local_dir(&mut rng, 0.03, 0.995)
        };
        if wr[2] < 0.03 {
            continue;
        }
        out.push((
            round_f32(to_world(t, b, n, wi)),
            round_f32(to_world(t, b, n, wr)),
        ));
    }
    out
}

// ===========================================================================
// GPU

/// One case = 32 vec4 (layout of `Case` in the shader below).
pub(super) const CASE_VEC4S: usize = 32;

pub(super) const ENTRY: &str = r#"
struct Case {
    wi: vec4<f32>, wr: vec4<f32>, t: vec4<f32>, b: vec4<f32>, n: vec4<f32>,
    // rgb = linear albedo, w = eta
    albedo1: vec4<f32>,
    // k_d, gamma_s, gamma_v (radians), coverage
    p1: vec4<f32>,
    albedo2: vec4<f32>,
    p2: vec4<f32>,
    off1a: vec4<f32>, off1b: vec4<f32>, off2a: vec4<f32>, off2b: vec4<f32>,
    // x: 1 = offset list, 0 = curve; y, z: offset counts; w: 1 = second thread set
    mode: vec4<f32>,
    curve1: array<vec4<f32>, 9>,
    curve2: array<vec4<f32>, 9>,
}
@group(0) @binding(0) var<storage, read> cases: array<Case>;
// Two per case: reference tier, fast tier.
@group(0) @binding(1) var<storage, read_write> results: array<vec4<f32>>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if i >= arrayLength(&cases) {
        return;
    }
    let c = cases[i];
    let wi = c.wi.xyz;
    let wr = c.wr.xyz;
    let warp = McFrame(c.t.xyz, c.b.xyz, c.n.xyz);
    let weft = McFrame(c.b.xyz, c.t.xyz, c.n.xyz);
    let th1 = McThread(c.albedo1.xyz, c.albedo1.w, c.p1.x, c.p1.y, c.p1.z);
    let th2 = McThread(c.albedo2.xyz, c.albedo2.w, c.p2.x, c.p2.y, c.p2.z);
    let use2 = c.mode.w > 0.5;
    let a2 = select(0.0, c.p2.w, use2);
    var r1 = vec4<f32>(0.0);
    var r2 = vec4<f32>(0.0);
    var f1 = vec4<f32>(0.0);
    var f2 = vec4<f32>(0.0);
    if c.mode.x > 0.5 {
        let n1 = i32(c.mode.y);
        let n2 = i32(c.mode.z);
        r1 = mc_thread_list_reference(warp, wi, wr, th1, c.off1a, c.off1b, n1);
        f1 = mc_thread_list_fast(warp, wi, wr, th1, c.off1a, c.off1b, n1);
        if use2 {
            r2 = mc_thread_list_reference(weft, wi, wr, th2, c.off2a, c.off2b, n2);
            f2 = mc_thread_list_fast(weft, wi, wr, th2, c.off2a, c.off2b, n2);
        }
    } else {
        r1 = mc_thread_curve_reference(warp, wi, wr, th1, c.curve1);
        f1 = mc_thread_curve_fast(warp, wi, wr, th1, c.curve1);
        if use2 {
            r2 = mc_thread_curve_reference(weft, wi, wr, th2, c.curve2);
            f2 = mc_thread_curve_fast(weft, wi, wr, th2, c.curve2);
        }
    }
    let ndi = dot(c.n.xyz, wi);
    let ndr = dot(c.n.xyz, wr);
    results[2u * i] = vec4<f32>(mc_combine(r1, r2, c.p1.w, a2, ndi, ndr), 0.0);
    results[2u * i + 1u] = vec4<f32>(mc_combine(f1, f2, c.p1.w, a2, ndi, ndr), 0.0);
}
"#;

/// The compute module: the engine-interface constants the library uses, then
/// lib/brdf.wgsl, lib/half.wgsl (with `weft_half` = f32), lib/microcylinder.wgsl,
/// lib/microcylinder_nodes.wgsl and the entry point.
pub(super) fn compose_shader() -> String {
    let root = materials_root();
    let read = |p: &str| {
        std::fs::read_to_string(root.join(p))
            .unwrap_or_else(|e| panic!("{}: {e}", root.join(p).display()))
    };
    // The model and reference, then the node-rule tiers (low, fast).
    let lib = read("lib/microcylinder.wgsl") + "\n" + &read("lib/microcylinder_nodes.wgsl");
    assert!(
        lib.contains(&format!("const MC_CURVE_SAMPLES: u32 = {CURVE_SAMPLES}u;")),
        "MC_CURVE_SAMPLES in lib/microcylinder.wgsl must be {CURVE_SAMPLES}"
    );
    // The library must stay pure: no material uniform, frame or binding
    // (comments aside).
    let code: String = lib
        .lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n");
    for forbidden in [
        "material.",
        "weft_frame",
        "@group",
        "@binding",
        "textureSample",
    ] {
        assert!(
            !code.contains(forbidden),
            "lib/microcylinder{{,_nodes}}.wgsl uses `{forbidden}`"
        );
    }
    // The low tier's code in the library computes in `weft_half`
    // (lib/half.wgsl): composed here in f32, as a material's f32 fallback.
    format!(
        "const WEFT_PI: f32 = 3.14159265358979;\nconst WEFT_INV_PI: f32 = 0.318309886183791;\nalias weft_half = f32;\n{}\n{}\n{}\n{}",
        read("lib/brdf.wgsl"),
        read("lib/half.wgsl"),
        lib,
        ENTRY
    )
}

pub(super) struct Case {
    pub(super) fabric: usize,
    pub(super) n: V3,
    pub(super) t: V3,
    pub(super) b: V3,
    pub(super) wi: V3,
    pub(super) wr: V3,
}

pub(super) fn pack_case(fab: &Fabric, c: &Case) -> [[f32; 4]; CASE_VEC4S] {
    let mut v = [[0.0f32; 4]; CASE_VEC4S];
    let v3 = |a: V3, w: f64| [a[0] as f32, a[1] as f32, a[2] as f32, w as f32];
    v[0] = v3(c.wi, 0.0);
    v[1] = v3(c.wr, 0.0);
    v[2] = v3(c.t, 0.0);
    v[3] = v3(c.b, 0.0);
    v[4] = v3(c.n, 0.0);
    v[5] = v3(fab.t1.albedo, fab.t1.eta);
    v[6] = [
        fab.t1.kd as f32,
        fab.t1.gamma_s as f32,
        fab.t1.gamma_v as f32,
        fab.a1 as f32,
    ];
    v[7] = v3(fab.t2.albedo, fab.t2.eta);
    v[8] = [
        fab.t2.kd as f32,
        fab.t2.gamma_s as f32,
        fab.t2.gamma_v as f32,
        fab.a2 as f32,
    ];
    let mut mode = [0.0f32, 0.0, 0.0, if fab.use2 { 1.0 } else { 0.0 }];
    for (j, p) in [&fab.p1, &fab.p2].into_iter().enumerate() {
        match p {
            Profile::List(o) => {
                mode[0] = 1.0;
                mode[1 + j] = o.len() as f32;
                for (k, x) in o.iter().enumerate() {
                    v[9 + 2 * j + k / 4][k % 4] = *x as f32;
                }
            }
            Profile::Curve(h) => {
                for (k, x) in h.iter().enumerate() {
                    v[14 + 9 * j + k / 4][k % 4] = *x as f32;
                }
            }
        }
    }
    v[13] = mode;
    v
}

/// The fabric as the GPU sees it (every input rounded to f32), so that the
/// comparison measures arithmetic only.
pub(super) fn as_f32(f: &Fabric) -> Fabric {
    let r = |x: f64| x as f32 as f64;
    let th = |t: &Thread| Thread {
        albedo: t.albedo.map(r),
        eta: r(t.eta),
        kd: r(t.kd),
        gamma_s: r(t.gamma_s),
        gamma_v: r(t.gamma_v),
        transmission: t.transmission,
    };
    let p = |p: &Profile| match p {
        Profile::List(o) => Profile::List(o.iter().map(|x| r(*x)).collect()),
        Profile::Curve(h) => Profile::Curve(h.iter().map(|x| r(*x)).collect()),
    };
    Fabric {
        name: f.name,
        t1: th(&f.t1),
        a1: r(f.a1),
        p1: p(&f.p1),
        t2: th(&f.t2),
        a2: r(f.a2),
        p2: p(&f.p2),
        use2: f.use2,
    }
}

pub(super) fn run_gpu(shader: &str, data: &[[f32; 4]], n_cases: usize) -> Vec<[f32; 4]> {
    let gpu = weft_render::Gpu::new().unwrap_or_else(|e| panic!("{e}"));
    eprintln!("adapter: {}", gpu.describe());
    let bytes = gpu
        .run_compute(
            shader,
            "main",
            bytemuck::cast_slice(data),
            (n_cases * 2 * 16) as u64,
            n_cases.div_ceil(64) as u32,
        )
        .unwrap_or_else(|e| panic!("wgpu: {e}"));
    bytemuck::cast_slice::<u8, [f32; 4]>(&bytes).to_vec()
}
