//! weft-render's integration tests, one binary: the runtime on the machine's
//! Vulkan adapter (`runtime`), state taken from the metadata alone
//! (`metadata_state`), and scene drawing (`scene`); `support` builds the
//! materials roots they draw, once.

mod metadata_state;
mod runtime;
mod scene;
mod support;
