//! weft-compiler's integration tests, one binary: scene builds, folding, and
//! the unread-parameter warning.

mod scene_build;
mod scene_fold;
mod unread_params;
