// Lies outside the diagnostics materials root: including it is an error.
fn outside() -> f32 {
    return 0.0;
}
