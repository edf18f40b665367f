//! weft-golden's integration tests, one binary: the lavapipe `auto` tier
//! chooser and the shading benchmark's small run.

mod auto_tier;
mod shading;
