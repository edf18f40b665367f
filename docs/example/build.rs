// build.rs: compile the project's materials into generated/ on every build.
fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!("cargo:rerun-if-changed=materials");
    let out = weft_compiler::build_library("materials".as_ref(), &Default::default(), &|_, _, _| {})
        .map_err(|(db, diags)| diags.render_plain(&db))?;
    weft_compiler::output::write_atomically("generated".as_ref(), &out.files, &[])?;
    Ok(())
}
