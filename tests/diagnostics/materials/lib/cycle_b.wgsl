// @include "lib/cycle_a.wgsl"
// The other half of the include cycle.
fn cycle_b() -> f32 {
    return 2.0;
}
