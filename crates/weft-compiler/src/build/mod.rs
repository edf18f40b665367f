//! The build-and-write plumbing around the compile stages: a materials
//! folder compiled into one output ([`library`]), the shared compile cache
//! ([`cache`]), shards ([`shard`]), reuse of unchanged outputs
//! ([`unchanged`]), and writing: atomic replacement ([`output`]), the
//! ownership mark that lets weft replace only what it wrote ([`ownership`]),
//! staging folders ([`staging`]), build stamps ([`stamp`]), whole-folder
//! builds ([`folder_build`]) and builds held in memory ([`in_memory`]).
//!
//! Data flows one way: this half calls `crate::compile` and `crate::scene`;
//! they never call back.

pub mod cache;
pub mod folder_build;
pub mod in_memory;
pub mod library;
pub mod output;
pub mod ownership;
pub mod shard;
pub mod staging;
pub mod stamp;
pub mod unchanged;
