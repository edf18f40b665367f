//! The per-family worker of `weft_gpu_stats::collect`: reads a request on
//! stdin, compiles on RADV's null device, prints the statistics as JSON.
//! Started by the library with `VK_ICD_FILENAMES` and `RADV_FORCE_FAMILY` set.

fn main() {
    std::process::exit(weft_gpu_stats::worker::serve_stdio());
}
