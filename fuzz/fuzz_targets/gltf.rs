#![no_main]
// Target: weft_fuzz::gltf (see src/lib.rs and docs/fuzzing.md).
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let _ = weft_fuzz::gltf(data);
});
