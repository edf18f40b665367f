// @include "lib/cycle_b.wgsl"
// Half of a deliberate include cycle (see bad/include_cycle.wgsl).
fn cycle_a() -> f32 {
    return 1.0;
}
