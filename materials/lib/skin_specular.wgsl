// The seed's skin specular (seed 004 sec. 3.2), shared by skin (its seed
// look) and face (whose shading is the skin's with the SDF shadow in place
// of N.L). Needs lib/forward.wgsl (WEFT_PI).

// The seed's DirectBDRF_DualLobeSpecular (sec. 3.2) as written, with
// `roughness` Unity's linear roughness (perceptual squared) and the 1/pi
// Unity folds into its lights restored; returns the term before x F0.
fn skin_seed_specular(n: vec3<f32>, l: vec3<f32>, h: vec3<f32>, roughness: f32, mask: f32, lobe_weight: f32) -> f32 {
    let n_dot_h = saturate(dot(n, h));
    let l_dot_h = saturate(dot(l, h));
    let r2 = roughness * roughness;
    let normalization = roughness * 4.0 + 2.0;
    let d = n_dot_h * n_dot_h * (r2 - 1.0) + 1.00001;
    // The seed names it nv but takes n.l.
    let nl = saturate(dot(n, l));
    let s_ao = mix(pow(0.75, 8.0), 1.0, saturate(-0.3 + nl * nl));
    let denom = d * d * max(0.1, l_dot_h * l_dot_h) * normalization;
    let ggx = r2 / denom;
    let second = 2.0 * r2 / denom * lobe_weight * mask;
    return (ggx / 2.0 + second) * s_ao / WEFT_PI;
}
