//! The shading benchmark on the committed generated/ tree, small and short:
//! timings come back from timestamp queries (lavapipe has them) and from the
//! CPU fallback, the reference tier has no error against itself and every
//! other tier some.

use std::path::Path;
use weft_golden::shading::{ShadingOptions, run};
use weft_render::FrameTimer;

fn generated() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../generated")
}

#[test]
fn small_bench_is_sane() {
    for cpu in [false, true] {
        let options = ShadingOptions {
            size: 48,
            frames: 3,
            warmup: 1,
            rounds: 1,
            force_cpu_timer: cpu,
            materials: vec!["standard".into()],
            ..Default::default()
        };
        let report = run(&generated(), &options, &mut |_| {}).expect("bench runs");
        if cpu {
            assert_eq!(report.timer, FrameTimer::CpuWall);
        } else if report.adapter.contains("llvmpipe") {
            assert_eq!(report.timer, FrameTimer::GpuTimestamp);
        }
        let [m] = &report.materials[..] else {
            panic!("one material measured")
        };
        assert_eq!(m.material, "standard");
        let reference = m.tiers.iter().find(|t| t.tier == "reference").unwrap();
        let fast = m.tiers.iter().find(|t| t.tier == "fast").unwrap();
        assert_eq!(
            (reference.flip_mean, reference.flip_p99, reference.rel_rmse),
            (0.0, 0.0, 0.0)
        );
        assert!(fast.flip_mean > 0.0 && fast.flip_mean < 0.1, "{fast:?}");
        assert!(fast.rel_rmse > 0.0 && fast.rel_rmse < 0.2, "{fast:?}");
        assert_eq!(fast.ratio_to_standard_fast, Some(1.0));
        for t in &m.tiers {
            assert!(t.gpu_ms > 0.0 && t.gpu_ms < 10_000.0, "{t:?}");
            assert!(t.gpu_ms_min <= t.gpu_ms);
            assert!(t.frames >= 3);
            assert!(t.spirv_fragment_instructions > 0);
            assert!(t.spirv_instructions > t.spirv_fragment_instructions);
        }
        // The report round-trips through the metadata type.
        let json = serde_json::to_string(m).unwrap();
        let back: weft_meta::Measurements = serde_json::from_str(&json).unwrap();
        assert_eq!(&back, m);
    }
}
