//! Bad and hostile input: every corpus file fails with its code at its line,
//! with a hint, and nothing is written; the fuzz targets' smoke run and the
//! PNG decompression bombs stay bounded.

mod diagnostics;
mod fuzz_smoke;
mod png_bombs;
mod scene_diagnostics;
