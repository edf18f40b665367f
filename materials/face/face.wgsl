// @include "lib/forward.wgsl"
// @include "lib/skin_specular.wgsl"
//
// face: the SDF face shadow of seed 004 sec. 4. Returns linear HDR radiance.
// See README.md.
//
// One tier (`stylised`, the material is `stylised = true`): a painted
// threshold map decides light and shadow from the light's horizontal
// direction relative to the head, not from the normal, so the shadow keeps
// the shape an artist drew (no speckles on the nose, a clean line down the
// cheek). The result replaces N.L as u in the skin's pre-integrated table.

// The light's horizontal angle round the head as the seed measures it.
struct FaceLight {
    // 0.5 - 0.5 forward.L_h: 0 with the light in front, 1 behind.
    f_dot_l: f32,
    // True for a light on the object's +X side: the map is read mirrored.
    from_right: bool,
}

fn face_light(l: vec3<f32>) -> FaceLight {
    // Object forward (+Z) and right (+X) in world space.
    let model = weft_object.model;
    let forward = weft_safe_normalize(model[2].xyz, vec3<f32>(0.0, 0.0, 1.0));
    let right = weft_safe_normalize(model[0].xyz, vec3<f32>(1.0, 0.0, 0.0));
    // The light projected to the horizontal plane (+Y up). A light straight
    // above or below has no horizontal direction: the seed's normalize would
    // give NaN; it counts as a light in front (the face lit).
    let l_h = weft_safe_normalize(vec3<f32>(l.x, 0.0, l.z), forward);
    var out: FaceLight;
    out.f_dot_l = dot(forward, l_h) * -0.5 + 0.5;
    out.from_right = dot(right, l_h) >= 0.0;
    return out;
}

// The seed's bias: smoothstep(-w, w, sdf - FdotL) with the map for a light
// on the left (SDF_L) or mirrored in u (SDF_R).
fn face_sdf_shadow(uv: vec2<f32>, light: FaceLight, soft: f32) -> f32 {
    // Both samples before the choice: derivatives need uniform control flow.
    let sdf_l = textureSample(face_sdf_map, material_sampler, uv).r;
    let sdf_r = textureSample(face_sdf_map, material_sampler, vec2<f32>(1.0 - uv.x, uv.y)).r;
    let sdf = select(sdf_l, sdf_r, light.from_right);
    // smoothstep with equal edges is undefined in WGSL: keep a width.
    let w = max(soft, 1e-4);
    return smoothstep(-w, w, sdf - light.f_dot_l);
}

@fragment
fn fs_main(in: WeftVaryings) -> @location(0) vec4<f32> {
    // ------------------------------------------------------------ surface
    let uv = weft_transform_uv(in.uv0, material.base_map_st);
    let base_rgba = material.base_color * textureSample(base_map, material_sampler, uv);
    let albedo = saturate(base_rgba.rgb);
    let alpha = saturate(base_rgba.a);
    let roughness = clamp(material.roughness, 0.05, 1.0);
    let f0 = clamp(material.specular, 0.0, 1.0);
    let mask = saturate(textureSample(specular_mask, material_sampler, uv).r);
    let shadow_mask = saturate(textureSample(shadow_mask_map, material_sampler, uv).r);

    // ------------------------------------------------------------ geometry
    let surface = weft_surface(in.world_position, in.world_normal);
    let v = surface.v;
    let n = surface.n;
    // The seed's curvature (sec. 3.1): |fwidth(N)| / |fwidth(P)| x factor,
    // clamped to [0.01, 0.99] so the lookup stays off the table's edges.
    let dn = length(fwidth(n));
    let dp = length(fwidth(in.world_position));
    let estimated = select(0.0, dn / dp, dp > 1e-12);
    let curvature = clamp(max(material.curvature_factor, 0.0) * estimated, 0.01, 0.99);
    let lit = weft_main_light_geometry(n, v);

    // ------------------------------------------------------------ SDF shadow
    var bias = face_sdf_shadow(uv, face_light(lit.l), material.face_soft_shadow) * shadow_mask;
    bias = clamp(bias, material.dark_bound, material.bright_bound);
    // The skin's table read with the shadow in place of N.L * 0.5 + 0.5.
    let falloff = max(table_skin_lut(vec2<f32>(bias, curvature)).rgb, vec3<f32>(0.0));

    // ------------------------------------------------------------ specular
    let specular = skin_seed_specular(n, lit.l, lit.h, roughness * roughness, mask, material.lobe_weight) * f0 * lit.n_dot_l;
    let kd = vec3<f32>(1.0 - f0);
    let light = weft_main_light_radiance();
    let direct = (kd * weft_diffuse_lambert(albedo) * falloff + vec3<f32>(specular)) * light;

    // ------------------------------------------------------------ indirect
    let env_brdf = weft_env_brdf_from_lut(vec3<f32>(f0), weft_env_brdf_lut(lit.n_dot_v, roughness));
    let indirect_diffuse = weft_sh_irradiance(n) * kd * albedo;
    let indirect_specular = weft_prefiltered_radiance(reflect(-v, n), roughness) * env_brdf * mask;
    let color = direct + indirect_diffuse + indirect_specular;
    let radiance = clamp(color, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF));
    return vec4<f32>(radiance, alpha);
}
