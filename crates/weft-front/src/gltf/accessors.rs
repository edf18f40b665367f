//! Vertex attributes as f32, whatever their component type: glTF 2.0's
//! float and normalised integer ones, and the integer types
//! `KHR_mesh_quantization` adds (positions and texture coordinates as
//! plain or normalised 8- and 16-bit integers, normals and tangents as
//! normalised signed ones). The node's transform (and
//! `KHR_texture_transform`) carries the dequantisation's scale, so what is
//! read here is the stored value, normalised when the accessor says so.
//!
//! Callers check the accessor first (`meshes::check_accessor`): its type is
//! one the attribute allows and every byte it names exists.

use super::document::GltfFile;
use gltf::accessor::{DataType, Item, Iter};

/// The extension that lets attributes use integer components.
pub const MESH_QUANTIZATION: &str = "KHR_mesh_quantization";

/// Whether the file declares `KHR_mesh_quantization` (it must, to use it).
pub fn quantized(file: &GltfFile) -> bool {
    file.document
        .extensions_used()
        .any(|e| e == MESH_QUANTIZATION)
}

/// One stored component as glTF reads it (§ 3.11, "Animations" and
/// "Meshes"): a normalised signed integer c is max(c / (2ⁿ⁻¹ − 1), −1), an
/// unsigned one c / (2ⁿ − 1); a plain integer is its value.
fn component(data_type: DataType, normalized: bool, raw: f64) -> f32 {
    let scale = match data_type {
        DataType::I8 => 127.0,
        DataType::U8 => 255.0,
        DataType::I16 => 32767.0,
        DataType::U16 => 65535.0,
        DataType::U32 => 4_294_967_295.0,
        DataType::F32 => return raw as f32,
    };
    if normalized {
        (raw / scale).max(-1.0) as f32
    } else {
        raw as f32
    }
}

/// The elements of `accessor` (sparse values applied), each of N components
/// of type S, converted to f32.
fn elements<S, const N: usize>(
    file: &GltfFile,
    accessor: &gltf::Accessor,
    to_f64: fn(S) -> f64,
) -> Option<Vec<[f32; N]>>
where
    S: Copy,
    [S; N]: Item,
{
    let (data_type, normalized) = (accessor.data_type(), accessor.normalized());
    let iter = Iter::<[S; N]>::new(accessor.clone(), |b: gltf::Buffer| {
        file.buffers.get(b.index()).map(Vec::as_slice)
    })?;
    Some(
        iter.map(|e| e.map(|c| component(data_type, normalized, to_f64(c))))
            .collect(),
    )
}

/// `accessor`'s elements as f32 vectors of N components. `None` when its
/// bytes cannot be read (the caller's check makes that an error).
pub fn read_f32<const N: usize>(file: &GltfFile, accessor: &gltf::Accessor) -> Option<Vec<[f32; N]>>
where
    [f32; N]: Item,
    [i8; N]: Item,
    [u8; N]: Item,
    [i16; N]: Item,
    [u16; N]: Item,
{
    match accessor.data_type() {
        DataType::F32 => elements::<f32, N>(file, accessor, f64::from),
        DataType::I8 => elements::<i8, N>(file, accessor, f64::from),
        DataType::U8 => elements::<u8, N>(file, accessor, f64::from),
        DataType::I16 => elements::<i16, N>(file, accessor, f64::from),
        DataType::U16 => elements::<u16, N>(file, accessor, f64::from),
        // No vertex attribute may be u32 (§ 3.7.2.1); indices are read apart.
        DataType::U32 => None,
    }
}

/// The bounds of a primitive's positions from its POSITION accessor's `min`
/// and `max` (which glTF requires), in the units the vertices are read in:
/// glTF stores the bounds as the raw component values, whatever
/// `normalized` says, so normalised integer bounds are scaled here as the
/// vertices are.
pub fn position_bounds(prim: &gltf::Primitive) -> Option<([f32; 3], [f32; 3])> {
    let accessor = prim.get(&gltf::Semantic::Positions)?;
    let (data_type, normalized) = (accessor.data_type(), accessor.normalized());
    let read = |v: Option<gltf::json::Value>| -> Option<[f32; 3]> {
        let values = v?;
        let values = values.as_array()?;
        if values.len() != 3 {
            return None;
        }
        let mut out = [0.0; 3];
        for (o, v) in out.iter_mut().zip(values) {
            *o = component(data_type, normalized, v.as_f64()?);
        }
        Some(out)
    };
    Some((read(accessor.min())?, read(accessor.max())?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn components_normalise_as_gltf_says() {
        assert_eq!(component(DataType::I8, true, -128.0), -1.0);
        assert_eq!(component(DataType::I8, true, 127.0), 1.0);
        assert_eq!(component(DataType::I16, true, -32767.0), -1.0);
        assert_eq!(component(DataType::U8, true, 255.0), 1.0);
        assert_eq!(component(DataType::U16, true, 65535.0), 1.0);
        assert_eq!(component(DataType::U16, false, 700.0), 700.0);
        assert_eq!(component(DataType::I8, false, -5.0), -5.0);
        assert_eq!(component(DataType::F32, true, 0.25), 0.25);
    }
}
