//! Library half of the `weft` CLI: text rendering shared with tests.

pub mod tables;
