use std::time::Instant;
use weft_render::*;
fn main() -> Result<()> {
    let t = Instant::now();
    let meta = "generated/standard/standard.meta.json";
    let mut m = Material::load(meta)?;
    m.apply_preset("gold")?;
    let lut = Luts::for_metadata(meta)?;
    println!("load {:?}", t.elapsed());
    let t = Instant::now();
    let env = EnvironmentMaps::sky(&SkyParams::default());
    println!("env {:?}", t.elapsed());
    let t = Instant::now();
    let gpu = Gpu::new()?;
    println!("gpu {:?}", t.elapsed());
    let t = Instant::now();
    let mut r = Renderer::new(gpu, &env, &lut)?;
    println!("renderer {:?}", t.elapsed());
    let opts = RenderOptions::default();
    let t = Instant::now();
    let p = r.prepare(&m, &opts)?;
    println!("prepare {:?}", t.elapsed());
    for _ in 0..2 {
        let t = Instant::now();
        let img = r.render_prepared(&p, &Scene::sphere(), &opts)?;
        println!("render {:?}", t.elapsed());
        let t = Instant::now();
        let _ = img.to_srgb8(Tonemap::Aces, 1.0);
        println!("tonemap {:?}", t.elapsed());
    }
    Ok(())
}
