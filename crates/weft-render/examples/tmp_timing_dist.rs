use weft_render::*;
fn main() -> Result<()> {
    let meta = "generated/standard/standard.meta.json";
    let m = Material::load(meta)?;
    let lut = Luts::for_metadata(meta)?;
    let env = EnvironmentMaps::sky(&SkyParams::default());
    let mut r = Renderer::new(Gpu::new()?, &env, &lut)?;
    let opts = RenderOptions {
        width: 512,
        height: 512,
        background: Background::Color([0.0; 4]),
        ..Default::default()
    };
    let p = r.prepare(&m, &opts)?;
    for cpu in [false, true, false, true] {
        let t = r.time_frames(
            &p,
            &Scene::sphere(),
            &opts,
            &TimingOptions {
                warmup: 3,
                frames: 30,
                force_cpu_timer: cpu,
            },
        )?;
        let mut v = t.ms.clone();
        v.sort_by(f64::total_cmp);
        println!(
            "{:?}: {:?}",
            t.timer,
            v.iter().map(|x| format!("{x:.1}")).collect::<Vec<_>>()
        );
    }
    Ok(())
}
