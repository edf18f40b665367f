//! The engine interface's numbers and names, stated once: bind groups, the
//! binding of each engine resource and the material's fixed bindings, and
//! the `resource.id` each group-0/2 binding carries. The compiler declares
//! and describes the bindings with these (`engine_interface.wgsl` is held to
//! [`ENGINE_BINDINGS`] by a test), weft-render binds by them, and
//! docs/engine-interface.md lists them.

/// Group 0: per frame (`weft_frame`, the environment, the LUTs).
pub const FRAME_GROUP: u32 = 0;
/// Group 1: per material (generated from the material's parameters).
pub const MATERIAL_GROUP: u32 = 1;
/// Group 2: per object (`weft_object`).
pub const OBJECT_GROUP: u32 = 2;

/// Group 1: the material uniform block (`material`, struct `WeftMaterial`).
pub const MATERIAL_UNIFORM_BINDING: u32 = 0;
/// Group 1: `material_sampler` (trilinear, repeat).
pub const MATERIAL_SAMPLER_BINDING: u32 = 1;
/// Group 1: `material_clamp_sampler` (trilinear, clamp to edge).
pub const MATERIAL_CLAMP_SAMPLER_BINDING: u32 = 2;
/// Group 1: the first texture; textures, cubes, gradient ramps and baked
/// tables follow in declaration order.
pub const FIRST_TEXTURE_BINDING: u32 = 3;

/// `resource.id` of `weft_frame`.
pub const FRAME: &str = "frame";
/// `resource.id` of `weft_environment`.
pub const ENVIRONMENT: &str = "environment";
/// `resource.id` of `weft_environment_sampler`.
pub const ENVIRONMENT_SAMPLER: &str = "environment_sampler";
/// `resource.id` of `weft_brdf_lut`.
pub const SPLIT_SUM_LUT: &str = "split_sum_lut";
/// `resource.id` of `weft_lut_sampler`.
pub const LUT_SAMPLER: &str = "lut_sampler";
/// `resource.id` of `weft_sheen_lut`.
pub const SHEEN_ALBEDO_LUT: &str = "sheen_albedo_lut";
/// `resource.id` of `weft_object`.
pub const OBJECT: &str = "object";

/// One binding of the engine interface (groups 0 and 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EngineBinding {
    /// `@group`.
    pub group: u32,
    /// `@binding`.
    pub binding: u32,
    /// The WGSL global's name.
    pub name: &'static str,
    /// The `resource.id` the metadata gives it.
    pub id: &'static str,
}

const fn engine(group: u32, binding: u32, name: &'static str, id: &'static str) -> EngineBinding {
    EngineBinding {
        group,
        binding,
        name,
        id,
    }
}

/// Every binding of the engine interface, by (group, binding).
pub const ENGINE_BINDINGS: [EngineBinding; 7] = [
    engine(FRAME_GROUP, 0, "weft_frame", FRAME),
    engine(FRAME_GROUP, 1, "weft_environment", ENVIRONMENT),
    engine(
        FRAME_GROUP,
        2,
        "weft_environment_sampler",
        ENVIRONMENT_SAMPLER,
    ),
    engine(FRAME_GROUP, 3, "weft_brdf_lut", SPLIT_SUM_LUT),
    engine(FRAME_GROUP, 4, "weft_lut_sampler", LUT_SAMPLER),
    engine(FRAME_GROUP, 5, "weft_sheen_lut", SHEEN_ALBEDO_LUT),
    engine(OBJECT_GROUP, 0, "weft_object", OBJECT),
];

/// The engine binding whose WGSL global is `name`.
pub fn engine_binding(name: &str) -> Option<&'static EngineBinding> {
    ENGINE_BINDINGS.iter().find(|b| b.name == name)
}

/// The `resource.id`s of [`ENGINE_BINDINGS`], in order.
pub const ENGINE_RESOURCE_IDS: [&str; ENGINE_BINDINGS.len()] = {
    let mut ids = [""; ENGINE_BINDINGS.len()];
    let mut i = 0;
    while i < ids.len() {
        ids[i] = ENGINE_BINDINGS[i].id;
        i += 1;
    }
    ids
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bindings_are_sorted_and_distinct() {
        for w in ENGINE_BINDINGS.windows(2) {
            assert!((w[0].group, w[0].binding) < (w[1].group, w[1].binding));
        }
        assert_eq!(
            ENGINE_RESOURCE_IDS,
            [
                "frame",
                "environment",
                "environment_sampler",
                "split_sum_lut",
                "lut_sampler",
                "sheen_albedo_lut",
                "object",
            ]
        );
    }
}
