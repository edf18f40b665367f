//! `EXT_mesh_gpu_instancing`: a node that draws its mesh once per element
//! of its instance accessors, each copy moved by its own translation ·
//! rotation · scale before the node's world transform (what Blender's "GPU
//! instances", gltfpack `-mi` and three.js's `InstancedMesh` export write).
//! weft draws a still scene, so each copy becomes an ordinary instance of
//! the scene; the scene's instance limit bounds how many a file may ask for.

use super::GltfError;
use super::accessors::{Allowed, Norm, check_accessor, quantized, read_finite};
use super::document::{GPU_INSTANCING, GltfFile};
use super::transform::Mat4;
use gltf::accessor::{DataType, Dimensions};
use serde_json::Value;

/// The instance attributes that move a copy; others are an error unless
/// application-specific (a leading `_`, which the extension reserves for
/// data a renderer may ignore).
const TRANSFORM_ATTRIBUTES: [&str; 3] = ["TRANSLATION", "ROTATION", "SCALE"];

/// The JSON pointer of a node's extension object.
fn pointer(node: usize) -> String {
    format!("/nodes/{node}/extensions/{GPU_INSTANCING}")
}

/// The accessor types the extension allows per attribute: floats, a
/// rotation also as normalised signed integers, and with
/// `KHR_mesh_quantization` translation and scale as integers too.
fn allowed(attribute: &str, quantized: bool) -> Vec<Allowed> {
    use DataType::{F32, I8, I16, U8, U16};
    let vec3 = Dimensions::Vec3;
    match attribute {
        "ROTATION" => vec![
            (F32, Dimensions::Vec4, Norm::Either),
            (I8, Dimensions::Vec4, Norm::Yes),
            (I16, Dimensions::Vec4, Norm::Yes),
        ],
        _ => {
            let mut types = vec![(F32, vec3, Norm::Either)];
            if quantized {
                types.extend([I8, U8, I16, U16].map(|t| (t, vec3, Norm::Either)));
            }
            types
        }
    }
}

/// The node's instance transforms (each T · R · S in the node's own
/// space), or `None` when the node does not use the extension. At most
/// `limit` instances are read: a file asking for more is an error before
/// any is read.
pub fn instance_transforms(
    file: &GltfFile,
    node: &gltf::Node,
    limit: usize,
) -> Result<Option<Vec<Mat4>>, GltfError> {
    let Some(extension) = node.extension_value(GPU_INSTANCING) else {
        return Ok(None);
    };
    let at = pointer(node.index());
    let hint = "EXT_mesh_gpu_instancing: `attributes` maps TRANSLATION, ROTATION and SCALE to accessors with one element per instance";
    if node.mesh().is_none() {
        return Err(file.error(
            &at,
            "the node has instances but no mesh".into(),
            "put the extension on the node that holds the mesh",
        ));
    }
    if node.skin().is_some() {
        return Err(file.error(
            &at,
            "a skinned node cannot be instanced: glTF poses a skinned mesh in world space, so every copy would land in one place".into(),
            "instance an unskinned mesh, or export each copy as a node of its own",
        ));
    }
    let Some(attributes) = extension.get("attributes").and_then(Value::as_object) else {
        return Err(file.error(&at, "the extension has no `attributes` object".into(), hint));
    };
    let mut streams: Vec<(&str, gltf::Accessor)> = Vec::new();
    for (name, index) in attributes {
        let attribute_at = format!("{at}/attributes/{name}");
        if name.starts_with('_') {
            continue;
        }
        if !TRANSFORM_ATTRIBUTES.contains(&name.as_str()) {
            return Err(file.error(
                &attribute_at,
                format!("`{name}` is not an instance attribute"),
                "the extension defines TRANSLATION, ROTATION and SCALE; application-specific ones begin with `_`",
            ));
        }
        let accessor = index
            .as_u64()
            .and_then(|i| file.document.accessors().nth(usize::try_from(i).ok()?))
            .ok_or_else(|| {
                file.error(
                    &attribute_at,
                    format!("{index} is not the index of an accessor of the file"),
                    hint,
                )
            })?;
        streams.push((name, accessor));
    }
    // Only application attributes: every copy is the node's own, in one
    // place, so one draw shows them all.
    let Some(count) = streams.first().map(|(_, a)| a.count()) else {
        return Ok(None);
    };
    if count == 0 {
        return Err(file.error(&at, "the accessors hold no instance".into(), hint));
    }
    if count > limit {
        return Err(file.error(
            &at,
            format!("{count} instances, where the scene has room for {limit} more copies of this mesh"),
            "weft draws each copy as an instance of the scene, which has a limit: draw fewer copies, or split the scene",
        ));
    }
    let mut translation = vec![[0.0f32; 3]; count];
    let mut rotation = vec![[0.0f32, 0.0, 0.0, 1.0]; count];
    let mut scale = vec![[1.0f32; 3]; count];
    let quantized = quantized(file);
    for (name, accessor) in &streams {
        if accessor.count() != count {
            return Err(file.error(
                &format!("{at}/attributes/{name}"),
                format!(
                    "{} elements, where the other attributes have {count}",
                    accessor.count()
                ),
                "every instance attribute has one element per instance",
            ));
        }
        let what = format!("instance {name}");
        check_accessor(file, accessor, &allowed(name, quantized), &what)?;
        match *name {
            "TRANSLATION" => translation = read_finite(file, accessor, &what)?,
            "SCALE" => scale = read_finite(file, accessor, &what)?,
            _ => rotation = read_finite(file, accessor, &what)?,
        }
    }
    let mut transforms = Vec::with_capacity(count);
    for i in 0..count {
        let Some(rotation) = unit_quaternion(rotation[i]) else {
            let accessor = streams
                .iter()
                .find(|(n, _)| *n == "ROTATION")
                .map(|(_, a)| a.index());
            return Err(file.error(
                &format!("/accessors/{}", accessor.unwrap_or_default()),
                format!("instance {i}'s ROTATION has no length, so it is no rotation"),
                "write unit quaternions (x, y, z, w)",
            ));
        };
        let trs = gltf::scene::Transform::Decomposed {
            translation: translation[i],
            rotation,
            scale: scale[i],
        };
        transforms.push(trs.matrix().map(|c| c.map(f64::from)));
    }
    Ok(Some(transforms))
}

/// `q` at unit length (normalised integers are only close to it), `None`
/// when it has none.
fn unit_quaternion(q: [f32; 4]) -> Option<[f32; 4]> {
    let len = q
        .iter()
        .map(|&x| f64::from(x) * f64::from(x))
        .sum::<f64>()
        .sqrt();
    if (len - 1.0).abs() < 1e-7 {
        Some(q)
    } else {
        (len > 1e-6).then(|| q.map(|x| (f64::from(x) / len) as f32))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quaternions_are_made_unit_length_or_refused() {
        assert_eq!(
            unit_quaternion([0.0, 0.0, 0.0, 2.0]),
            Some([0.0, 0.0, 0.0, 1.0])
        );
        assert_eq!(unit_quaternion([0.0; 4]), None);
        let q = unit_quaternion([0.0, 0.0, 32767.0 / 32767.0, 23170.0 / 32767.0]).unwrap();
        let len: f32 = q.iter().map(|x| x * x).sum();
        assert!((len - 1.0).abs() < 1e-6);
    }
}
