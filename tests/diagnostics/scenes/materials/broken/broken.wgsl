// Never composed: broken.toml fails before the WGSL is compiled.
