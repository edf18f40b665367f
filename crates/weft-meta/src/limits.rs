//! WebGPU device limits: the defaults every variant is checked against at
//! build time, and the raised limits a material declares (`[limits]` in its
//! TOML), which its metadata states so that an engine requests them.

#[cfg(feature = "schema")]
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// One device limit weft checks: its key (in the material TOML's `[limits]`
/// and in [`DeviceLimits`]), WebGPU's name for it and WebGPU's default.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LimitSpec {
    pub key: &'static str,
    pub webgpu: &'static str,
    pub default: u64,
    /// The largest value the limit may be given (u32 limits are GPUSize32).
    pub max: u64,
}

const U32: u64 = u32::MAX as u64;

/// Every limit weft checks, with WebGPU's defaults (the limits every WebGPU
/// device supports).
pub const LIMITS: [LimitSpec; 8] = [
    LimitSpec {
        key: "max_bind_groups",
        webgpu: "maxBindGroups",
        default: 4,
        max: U32,
    },
    LimitSpec {
        key: "max_bindings_per_bind_group",
        webgpu: "maxBindingsPerBindGroup",
        default: 1000,
        max: U32,
    },
    LimitSpec {
        key: "max_uniform_buffer_binding_size",
        webgpu: "maxUniformBufferBindingSize",
        default: 65536,
        max: u64::MAX,
    },
    LimitSpec {
        key: "max_uniform_buffers_per_shader_stage",
        webgpu: "maxUniformBuffersPerShaderStage",
        default: 12,
        max: U32,
    },
    LimitSpec {
        key: "max_sampled_textures_per_shader_stage",
        webgpu: "maxSampledTexturesPerShaderStage",
        default: 16,
        max: U32,
    },
    LimitSpec {
        key: "max_samplers_per_shader_stage",
        webgpu: "maxSamplersPerShaderStage",
        default: 16,
        max: U32,
    },
    LimitSpec {
        key: "max_vertex_attributes",
        webgpu: "maxVertexAttributes",
        default: 16,
        max: U32,
    },
    LimitSpec {
        key: "max_inter_stage_shader_variables",
        webgpu: "maxInterStageShaderVariables",
        default: 16,
        max: U32,
    },
];

/// The spec of the limit named `key`.
pub fn limit_spec(key: &str) -> Option<&'static LimitSpec> {
    LIMITS.iter().find(|l| l.key == key)
}

/// Device limits above WebGPU's defaults that a material declares in its
/// `[limits]` table. Every variant of the material is checked against these
/// (and WebGPU's defaults for the rest); an engine must request at least
/// these values when it creates the device. A limit not listed is WebGPU's
/// default.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct DeviceLimits {
    /// WebGPU `maxBindGroups` (default 4): bind groups a pipeline layout may have.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_bind_groups: Option<u64>,
    /// WebGPU `maxBindingsPerBindGroup` (default 1000): one more than the largest
    /// `@binding` number a bind group may use.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_bindings_per_bind_group: Option<u64>,
    /// WebGPU `maxUniformBufferBindingSize` (default 65536): the largest uniform
    /// buffer binding, in bytes.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_uniform_buffer_binding_size: Option<u64>,
    /// WebGPU `maxUniformBuffersPerShaderStage` (default 12): uniform buffers one
    /// shader stage may use.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_uniform_buffers_per_shader_stage: Option<u64>,
    /// WebGPU `maxSampledTexturesPerShaderStage` (default 16): sampled textures one
    /// shader stage may use.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_sampled_textures_per_shader_stage: Option<u64>,
    /// WebGPU `maxSamplersPerShaderStage` (default 16): samplers one shader stage
    /// may use.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_samplers_per_shader_stage: Option<u64>,
    /// WebGPU `maxVertexAttributes` (default 16): vertex attributes a vertex stage
    /// may read, and one more than the largest vertex `@location`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_vertex_attributes: Option<u64>,
    /// WebGPU `maxInterStageShaderVariables` (default 16): user-defined variables
    /// (`@location`s) passed from the vertex to the fragment stage, and one more
    /// than the largest such location.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_inter_stage_shader_variables: Option<u64>,
}

impl DeviceLimits {
    fn slot(&mut self, key: &str) -> Option<&mut Option<u64>> {
        Some(match key {
            "max_bind_groups" => &mut self.max_bind_groups,
            "max_bindings_per_bind_group" => &mut self.max_bindings_per_bind_group,
            "max_uniform_buffer_binding_size" => &mut self.max_uniform_buffer_binding_size,
            "max_uniform_buffers_per_shader_stage" => {
                &mut self.max_uniform_buffers_per_shader_stage
            }
            "max_sampled_textures_per_shader_stage" => {
                &mut self.max_sampled_textures_per_shader_stage
            }
            "max_samplers_per_shader_stage" => &mut self.max_samplers_per_shader_stage,
            "max_vertex_attributes" => &mut self.max_vertex_attributes,
            "max_inter_stage_shader_variables" => &mut self.max_inter_stage_shader_variables,
            _ => return None,
        })
    }

    /// Every limit's key and declared value, in [`LIMITS`] order.
    pub fn entries(&self) -> [(&'static str, Option<u64>); 8] {
        [
            ("max_bind_groups", self.max_bind_groups),
            (
                "max_bindings_per_bind_group",
                self.max_bindings_per_bind_group,
            ),
            (
                "max_uniform_buffer_binding_size",
                self.max_uniform_buffer_binding_size,
            ),
            (
                "max_uniform_buffers_per_shader_stage",
                self.max_uniform_buffers_per_shader_stage,
            ),
            (
                "max_sampled_textures_per_shader_stage",
                self.max_sampled_textures_per_shader_stage,
            ),
            (
                "max_samplers_per_shader_stage",
                self.max_samplers_per_shader_stage,
            ),
            ("max_vertex_attributes", self.max_vertex_attributes),
            (
                "max_inter_stage_shader_variables",
                self.max_inter_stage_shader_variables,
            ),
        ]
    }

    /// The declared value of the limit `key` (None: WebGPU's default applies).
    pub fn declared(&self, key: &str) -> Option<u64> {
        self.entries()
            .into_iter()
            .find(|(k, _)| *k == key)
            .and_then(|(_, v)| v)
    }

    /// Declares `key` (one of [`LIMITS`]); false for an unknown key.
    pub fn declare(&mut self, key: &str, value: u64) -> bool {
        match self.slot(key) {
            Some(v) => {
                *v = Some(value);
                true
            }
            None => false,
        }
    }

    /// The limit in force for `key`: the declared value, else WebGPU's default.
    pub fn get(&self, key: &str) -> u64 {
        self.declared(key)
            .or_else(|| limit_spec(key).map(|l| l.default))
            .unwrap_or(u64::MAX)
    }

    /// Raises every limit to at least `other`'s declared value (the limits a
    /// scene of several materials needs).
    pub fn raise_to(&mut self, other: &DeviceLimits) {
        for (key, value) in other.entries() {
            if let Some(v) = value
                && self.declared(key).is_none_or(|mine| mine < v)
            {
                self.declare(key, v);
            }
        }
    }

    /// True when nothing is declared (every limit is WebGPU's default).
    pub fn is_default(&self) -> bool {
        LIMITS.iter().all(|l| self.declared(l.key).is_none())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_limit_has_a_field() {
        let mut d = DeviceLimits::default();
        assert!(d.is_default());
        let order: Vec<&str> = d.entries().iter().map(|(k, _)| *k).collect();
        assert_eq!(order, LIMITS.map(|l| l.key));
        for (i, l) in LIMITS.iter().enumerate() {
            assert_eq!(d.get(l.key), l.default);
            assert!(d.declare(l.key, l.default + i as u64 + 1), "{}", l.key);
            assert_eq!(d.get(l.key), l.default + i as u64 + 1);
        }
        assert!(!d.declare("max_texture_dimension_2d", 1));
        let mut raised = DeviceLimits::default();
        raised.declare("max_bind_groups", 100);
        raised.declare("max_vertex_attributes", 17);
        raised.raise_to(&d);
        assert_eq!(raised.get("max_bind_groups"), 100);
        assert_eq!(
            raised.get("max_vertex_attributes"),
            d.get("max_vertex_attributes")
        );
        assert_eq!(
            raised.get("max_samplers_per_shader_stage"),
            d.get("max_samplers_per_shader_stage")
        );
        // Serialised keys are the TOML keys.
        let json = serde_json::to_value(&d).unwrap();
        let mut keys: Vec<&str> = json
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str)
            .collect();
        keys.sort();
        let mut want: Vec<&str> = LIMITS.iter().map(|l| l.key).collect();
        want.sort();
        assert_eq!(keys, want);
    }
}
