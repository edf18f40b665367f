//! Feature unification only (see Cargo.toml): no code. xtask depends on
//! this crate so that `cargo xtask regenerate` builds every shared
//! dependency with the features `cargo test --workspace` uses, and the test
//! command finds them already built.
