// A library file with a mistake (an undefined identifier), for
// bad/wgsl_error_in_include.toml.

fn broken_helper(uv: vec2<f32>) -> vec2<f32> {
    return uv * scale;
}
