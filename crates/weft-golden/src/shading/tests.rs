//! SPIR-V counting and the image error of an image against itself.

use super::*;
use weft_render::HdrImage;

#[test]
fn spirv_counts_follow_calls_from_the_fragment_entry() {
    // Header, OpEntryPoint Fragment %10, two functions: %10 calls %11.
    let mut w: Vec<u32> = vec![0x0723_0203, 0x0001_0000, 0, 20, 0];
    w.extend([(4 << 16) | 15, 4, 10, 0]); // OpEntryPoint Fragment %10 ""
    w.extend([(2 << 16) | 19, 1]); // OpTypeVoid %1
    w.extend([(5 << 16) | 54, 1, 11, 0, 2]); // OpFunction %11
    w.extend([(1 << 16) | 56]); // OpFunctionEnd
    w.extend([(5 << 16) | 54, 1, 10, 0, 2]); // OpFunction %10
    w.extend([(4 << 16) | 57, 1, 12, 11]); // OpFunctionCall %11
    w.extend([(1 << 16) | 56]); // OpFunctionEnd
    w.extend([(5 << 16) | 54, 1, 13, 0, 2]); // OpFunction %13 (unreached)
    w.extend([(1 << 16) | 56]);
    let bytes: Vec<u8> = w.iter().flat_map(|x| x.to_le_bytes()).collect();
    assert_eq!(spirv_instruction_counts(&bytes).unwrap(), (9, 5));
}

#[test]
fn an_image_has_no_error_against_itself() {
    let img = HdrImage {
        width: 4,
        height: 4,
        pixels: (0..16)
            .map(|i| {
                if i % 3 == 0 {
                    [0.0; 4]
                } else {
                    [i as f32 * 0.1, 0.5, 0.2, 1.0]
                }
            })
            .collect(),
    };
    let e = image_error(&img, &img);
    assert_eq!((e.flip_mean, e.flip_p99, e.rel_rmse), (0.0, 0.0, 0.0));
    assert_eq!(e.pixels, 10);
}
