// @include "lib/forward.wgsl"
// @include "lib/eye.wgsl"
//
// eye: a character's eye (seed 004 sec. 5 and the matcap of sec. 6). Returns
// linear HDR radiance. See README.md for the derivations.
//
// The mesh is a spherical eyeball looking along object +Z (the bust's eyes,
// the preview sphere): its unit object-space normal is the point's position
// in the eye frame of lib/eye.wgsl, and the eye's uv is the front
// projection of that point (the bust's uv0), so one rule serves every
// spherical eye mesh whatever its uv layout.
//
// Tiers (WEFT_TIER):
//   reference = the view ray through the cornea sphere, refracted onto the
//               iris plane (eye_refracted); the iris lit through the cornea
//               (Fresnel transmission of the view and of the light, the light
//               direction refracted), SH ambient on the iris plane; GGX
//               (correlated Smith, exact dielectric Fresnel) and the
//               split-sum environment on the cornea, or on the eyeball where
//               the ray misses the cornea (sclera: Lambert + the same
//               specular).
//   fast      = the parallax lookup (eye_parallax: iris = p - v.xy h / IOR,
//               the cornea normal above p), Schlick's Fresnel for the
//               tear film (eye_fresnel) and standard fast's GGX lobe
//               (eye_ggx); otherwise the reference's lighting.
//   seed      = a look: the seed's offset uv + height * view_os.xy (y
//               flipped), the matcap at the V x N-corrected view-space
//               normal added to the albedo, lit without shadow (light / pi +
//               SH ambient) and dimmed when back-lit.
// All tiers: back-light dimming 1 - dimming * saturate(-F.L).

@fragment
fn fs_main(in: WeftVaryings) -> @location(0) vec4<f32> {
    let model = weft_object.model;
    let model3 = mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz);
    let nm = weft_object.normal_matrix;
    let normal3 = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz);

    // World: view, normal, light. Eye frame: world normals map back to object
    // space by the model's transpose (n_world ~ M^-T n_obj), directions by the
    // normal matrix's transpose (M^-1 = (M^-T)^T).
    let surface = weft_surface(in.world_position, in.world_normal);
    let v = surface.v;
    let n = surface.n;
    let l = weft_main_light_direction();
    let p = weft_safe_normalize(transpose(model3) * n, vec3<f32>(0.0, 0.0, 1.0));
    let v_eye = weft_safe_normalize(transpose(normal3) * v, vec3<f32>(0.0, 0.0, 1.0));
    let forward = weft_safe_normalize(model3 * vec3<f32>(0.0, 0.0, 1.0), n);
    let dimming = 1.0 - saturate(material.backlight_dimming) * saturate(-dot(forward, l));
    let light = weft_main_light_radiance();

    var color: vec3<f32>;
    if WEFT_TIER == TIER_SEED {
        color = eye_seed(p, v_eye, n, in.world_position, light);
    } else {
        let cornea = eye_cornea(material.iris_radius, material.cornea_height);
        let ior = max(material.cornea_ior, 1.0);
        var look: EyeLookup;
        if WEFT_TIER == TIER_REFERENCE {
            look = eye_refracted(p, v_eye, cornea, ior);
        } else {
            look = eye_parallax(p, v_eye, cornea, ior);
        }
        color = eye_physical(look, n, v, l, normal3, ior, light);
    }
    let radiance = clamp(color * dimming, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF));
    return vec4<f32>(radiance, 1.0);
}

// ---------------------------------------------------------------- albedo

// Procedural iris at `rho` (distance from the axis over the iris radius, 1
// at the limbus) and angle `a`: a near-black pupil, the collarette colour
// blending into the iris colour, radial fibres, and the darker limbal ring.
fn eye_procedural_iris(rho: f32, a: f32) -> vec3<f32> {
    let pupil = clamp(material.pupil_size, 0.0, 0.95);
    let t = saturate((rho - pupil) / (1.0 - pupil));
    var c = mix(material.iris_inner_color.rgb, material.iris_color.rgb, smoothstep(0.05, 0.5, t));
    // Two incommensurate angular frequencies, phase-shifted along the radius,
    // read as the stroma's radial fibres; in [0.64, 1].
    let fibres = 0.82 + 0.1 * sin(a * 23.0 + 6.0 * t) + 0.08 * sin(a * 41.0 - 9.0 * t + 1.3);
    c = c * fibres;
    let w = saturate(material.limbus_width);
    c = c * (1.0 - 0.8 * smoothstep(1.0 - w, 1.0, rho));
    // Pupil edge over 2% of the iris radius.
    return mix(vec3<f32>(0.01), c, smoothstep(pupil - 0.02, pupil + 0.02, rho));
}

// Albedo of the eye at eye-frame xy `q`: the iris inside the limbus, the
// sclera outside, blended over 3% of the iris radius; only sclera where
// `front` is false (the back of the eyeball, projected onto the same disc).
fn eye_albedo(q: vec2<f32>, front: bool) -> vec3<f32> {
    let r = clamp(material.iris_radius, 0.05, 0.95);
    let rho = length(q) / r;
    var iris: vec3<f32>;
    if IRIS_MAP {
        // The iris square: the limbus on the inscribed circle of radius 0.5.
        let iris_uv = vec2<f32>(0.5, 0.5) + vec2<f32>(q.x, -q.y) * (0.5 / r);
        iris = material.iris_color.rgb * textureSample(iris_map, material_clamp_sampler, iris_uv).rgb;
    } else {
        // atan2 is undefined at the origin (inside the pupil): any angle does.
        let qa = select(vec2<f32>(1.0, 0.0), q, dot(q, q) > 1e-12);
        iris = eye_procedural_iris(rho, atan2(qa.y, qa.x));
    }
    let sclera = material.sclera_color.rgb
        * textureSample(sclera_map, material_sampler, eye_uv_from_xy(q)).rgb;
    let to_sclera = select(1.0, smoothstep(0.985, 1.015, rho), front);
    return saturate(mix(iris, sclera, to_sclera));
}

// ---------------------------------------------------------------- fast / reference

// Lighting shared by fast and reference, given where the view ray reaches the
// iris and the surface it enters (world space: n the mesh normal, v, l).
fn eye_physical(
    look: EyeLookup, n: vec3<f32>, v: vec3<f32>, l: vec3<f32>,
    normal3: mat3x3<f32>, ior: f32, light: vec3<f32>,
) -> vec3<f32> {
    let albedo = eye_albedo(look.iris, look.through_cornea > 0.0 || look.normal.z > 0.0);
    let roughness = weft_clamp_roughness(1.0 - saturate(material.cornea_smoothness));
    // The wet surface the ray enters: the cornea where it crosses it, else
    // the eyeball (sclera).
    let s = weft_safe_normalize(normal3 * look.normal, n);
    let s_dot_v = weft_clamp_cos(dot(s, v));
    let s_dot_l = saturate(dot(s, l));

    // Specular of the tear film: GGX, height-correlated Smith, exact
    // dielectric Fresnel; the environment by the split-sum LUT with F0 of
    // the IOR. The view leaves and the light enters the cornea with
    // transmission 1 - F.
    let h = weft_safe_normalize(l + v, s);
    let f = eye_fresnel(dot(v, h), ior);
    let direct_spec = eye_ggx(s, h, s_dot_v, s_dot_l, roughness) * f * s_dot_l;
    let f0 = vec3<f32>(weft_f0_from_ior(ior));
    let env = weft_prefiltered_radiance(reflect(-v, s), roughness)
        * weft_env_brdf_from_lut(f0, weft_env_brdf_lut(s_dot_v, roughness));
    let specular = (light * direct_spec + env) * max(material.specular_strength, 0.0);
    // Diffuse: the sclera (Lambert on the eyeball) or, behind the cornea,
    // the iris on the plane facing the eye's axis. The view leaves through
    // the cornea (transmission 1 - F(s.v)); the light enters through it,
    // bent by Snell's law, with its own transmission. through_cornea is
    // exactly 0 or 1, so one SH evaluation at the chosen normal serves both
    // (it was two, blended by that weight: the same value, ~40 more
    // instructions on AMD's compiler).
    let on_iris = look.through_cornea > 0.0;
    let iris_n = weft_safe_normalize(normal3 * vec3<f32>(0.0, 0.0, 1.0), n);
    let l_in = refract(-l, s, 1.0 / ior);
    // No light reaches the iris from behind the cornea's horizon.
    let iris_cos = select(0.0, saturate(dot(iris_n, -l_in)), s_dot_l > 0.0);
    let t_v = 1.0 - eye_fresnel(s_dot_v, ior);
    let t_l = 1.0 - eye_fresnel(s_dot_l, ior);
    let diffuse_n = select(n, iris_n, on_iris);
    let diffuse_cos = select(saturate(dot(n, l)), iris_cos * t_l, on_iris);
    let transmission = select(1.0, t_v, on_iris);
    let diffuse = albedo * transmission * (light * (WEFT_INV_PI * diffuse_cos) + weft_sh_irradiance(diffuse_n));

    return diffuse + specular;
}

// The tear film's Fresnel reflectance at cos_i: exact for a dielectric
// (Walter et al. 2007) in the reference, Schlick's approximation with the
// same normal-incidence value in fast. Schlick is worst near grazing and
// for low IORs: 0.050 below the exact value at IOR 1.376 (cos 0.10), 0.068
// at IOR 1.3; over the error grid it moves fast's worst FLIP from 0.0324 to
// 0.0334 and saves three square roots and six divisions (README "Tiers").
fn eye_fresnel(cos_i: f32, ior: f32) -> f32 {
    if WEFT_TIER == TIER_REFERENCE {
        return weft_f_dielectric(cos_i, ior);
    }
    return weft_f_schlick(vec3<f32>(weft_f0_from_ior(ior)), cos_i).x;
}

// GGX D V of the tear film: the reference's exact forms; in fast, standard's
// fast lobe (Hammon's visibility refined by one Newton step, no square root;
// D from n.h).
fn eye_ggx(s: vec3<f32>, h: vec3<f32>, s_dot_v: f32, s_dot_l: f32, roughness: f32) -> f32 {
    if WEFT_TIER == TIER_REFERENCE {
        return weft_d_ggx_nh(s, h, roughness) * weft_v_smith_ggx_correlated(s_dot_v, s_dot_l, roughness);
    }
    return weft_d_ggx(saturate(dot(s, h)), roughness) * weft_v_smith_ggx_correlated_newton(s_dot_v, s_dot_l, roughness);
}

// ---------------------------------------------------------------- seed

// Seed 004 sec. 5-6: the eye texture at the parallax-offset uv, the matcap
// added, lit unshadowed (the seed's eyes take no shadow).
fn eye_seed(p: vec3<f32>, v_eye: vec3<f32>, n: vec3<f32>, world_position: vec3<f32>, light: vec3<f32>) -> vec3<f32> {
    // The seed offsets the whole eye texture; the back of the eyeball
    // (p.z <= 0) shows the sclera.
    let uv = eye_seed_uv(eye_uv_from_xy(p.xy), v_eye, material.parallax_height);
    let albedo = eye_albedo(eye_xy_from_uv(uv), p.z > 0.0);

    // Matcap: view-space normal and camera -> point direction; the seed's
    // correction (-(V x N).y, (V x N).x) is the normal's xy for a point on
    // the view axis and follows the view off-axis. Its v is flipped here:
    // Unity's uv runs up, WGSL's down, and the image's top must be up.
    let view = weft_frame.view;
    let view3 = mat3x3<f32>(view[0].xyz, view[1].xyz, view[2].xyz);
    let n_vs = weft_safe_normalize(view3 * n, vec3<f32>(0.0, 0.0, 1.0));
    let d_vs = weft_safe_normalize((view * vec4<f32>(world_position, 1.0)).xyz, vec3<f32>(0.0, 0.0, -1.0));
    let vxn = cross(d_vs, n_vs);
    let matcap_uv = vec2<f32>(0.5 - 0.5 * vxn.y, 0.5 - 0.5 * vxn.x);
    var matcap: vec3<f32>;
    if MATCAP_MAP {
        matcap = textureSample(matcap_map, material_clamp_sampler, matcap_uv).rgb;
    } else {
        matcap = eye_procedural_matcap(matcap_uv);
    }
    let base = albedo + matcap * max(material.matcap_intensity, 0.0);
    return base * (light * WEFT_INV_PI + weft_sh_irradiance(n));
}

// A stand-in matcap: a soft window highlight up and to the left of the
// sphere's centre and a faint bounce on the lower right, in matcap uv (v
// down).
fn eye_procedural_matcap(uv: vec2<f32>) -> vec3<f32> {
    let key = 1.0 - smoothstep(0.03, 0.08, length(uv - vec2<f32>(0.36, 0.3)));
    let bounce = 1.0 - smoothstep(0.02, 0.09, length(uv - vec2<f32>(0.66, 0.72)));
    return vec3<f32>(key + 0.25 * bounce);
}
