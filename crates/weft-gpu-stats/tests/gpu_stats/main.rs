//! weft-gpu-stats' integration tests, one binary, on RADV's null device (no
//! GPU; needs `mesa-vulkan-drivers`): the library's statistics (`radv`) and
//! the loop-aware model (`loops`).

mod loops;
mod radv;
