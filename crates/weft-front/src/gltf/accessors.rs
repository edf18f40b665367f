//! Vertex attributes as f32, whatever their component type: glTF 2.0's
//! float and normalised integer ones, and the integer types
//! `KHR_mesh_quantization` adds (positions and texture coordinates as
//! plain or normalised 8- and 16-bit integers, normals and tangents as
//! normalised signed ones). The node's transform (and
//! `KHR_texture_transform`) carries the dequantisation's scale, so what is
//! read here is the stored value, normalised when the accessor says so.
//!
//! [`check_accessor`] comes first: the accessor's type is one the attribute
//! allows and every byte it names exists; then [`read_finite`] reads it.

use super::GltfError;
use super::document::{GltfFile, MESH_QUANTIZATION};
use gltf::accessor::{DataType, Dimensions, Item, Iter};

/// The most vertices (and indices) one primitive may have.
pub const MAX_PRIMITIVE_VERTICES: usize = 1 << 24;

/// What an accessor's `normalized` may be for one component type.
#[derive(Clone, Copy)]
pub enum Norm {
    /// Integers read as fractions (normalised colours, core texture coordinates).
    Yes,
    /// Integers read as their values (KHR_mesh_quantization's positions and
    /// texture coordinates may be either).
    Either,
}

impl Norm {
    fn accepts(self, normalized: bool) -> bool {
        match self {
            Norm::Yes => normalized,
            Norm::Either => true,
        }
    }
}

/// One accepted (component type, type, `normalized`). Floats and indices
/// accept either flag: it does not change what they read.
pub type Allowed = (DataType, Dimensions, Norm);

fn element_size(data_type: DataType, dims: Dimensions) -> usize {
    data_type.size() * dims.multiplicity()
}

/// Checks an accessor's bytes lie where the file says: a view inside its
/// buffer, every element (stride apart) inside the view, sparse indices and
/// values inside theirs. `allowed` lists the (component type, type,
/// `normalized`) the semantic may have.
pub fn check_accessor(
    file: &GltfFile,
    accessor: &gltf::Accessor,
    allowed: &[Allowed],
    what: &str,
) -> Result<(), GltfError> {
    let pointer = format!("/accessors/{}", accessor.index());
    let err = |message: String| {
        file.error(
            &pointer,
            message,
            "re-export the file; the accessor does not fit its data",
        )
    };
    let (data_type, dims) = (accessor.data_type(), accessor.dimensions());
    let normalized = accessor.normalized();
    if !allowed
        .iter()
        .any(|a| a.0 == data_type && a.1 == dims && a.2.accepts(normalized))
    {
        let normalised = if normalized && data_type != DataType::F32 {
            " normalised"
        } else {
            ""
        };
        return Err(file.error(
            &pointer,
            format!(
                "{what}: a {dims:?} of{normalised} {data_type:?}, which glTF does not allow here"
            ),
            "glTF 2.0 § 3.7.2.1 lists each attribute's accessor types; \
             KHR_mesh_quantization (declared in extensionsUsed) adds integer ones",
        ));
    }
    let count = accessor.count();
    if count == 0 || count > MAX_PRIMITIVE_VERTICES {
        return Err(err(format!(
            "{what}: {count} elements; weft reads 1 to {MAX_PRIMITIVE_VERTICES} per primitive"
        )));
    }
    let size = element_size(data_type, dims);
    let fits = |view: gltf::buffer::View,
                offset: usize,
                count: usize,
                size: usize|
     -> Result<(), GltfError> {
        let view_pointer = format!("/bufferViews/{}", view.index());
        let buffer_len = file.buffers[view.buffer().index()].len();
        if view
            .offset()
            .checked_add(view.length())
            .is_none_or(|end| end > buffer_len)
        {
            return Err(file.error(
                &view_pointer,
                format!(
                    "the view's {} bytes at {} run past its buffer's {buffer_len}",
                    view.length(),
                    view.offset()
                ),
                "re-export the file",
            ));
        }
        let stride = view.stride().unwrap_or(size);
        if stride < size {
            return Err(file.error(
                &view_pointer,
                format!("byteStride {stride} is below the element size {size}"),
                "re-export the file",
            ));
        }
        let end = (count - 1)
            .checked_mul(stride)
            .and_then(|n| n.checked_add(size))
            .and_then(|n| n.checked_add(offset));
        if end.is_none_or(|end| end > view.length()) {
            return Err(err(format!(
                "{what}: {count} elements of {size} bytes (stride {stride}) at offset {offset} run past its view's {} bytes",
                view.length()
            )));
        }
        Ok(())
    };
    match accessor.view() {
        Some(view) => fits(view, accessor.offset(), count, size)?,
        // glTF reads such an accessor as zeros (§ 3.6.2.1): a placeholder
        // no exporter writes for data it means to be drawn.
        None if accessor.sparse().is_none() => {
            return Err(file.error(
                &pointer,
                format!(
                    "{what}: no bufferView and no sparse values, so glTF reads every element as zero"
                ),
                "weft does not draw an attribute or index list of zeros; re-export the file with the mesh's data",
            ));
        }
        None => {}
    }
    if let Some(sparse) = accessor.sparse() {
        let n = sparse.count();
        if n == 0 || n > count {
            return Err(err(format!(
                "{what}: {n} sparse values for {count} elements"
            )));
        }
        let indices = sparse.indices();
        fits(
            indices.view(),
            indices.offset(),
            n,
            indices.index_type().size(),
        )?;
        let values = sparse.values();
        fits(values.view(), values.offset(), n, size)?;
    }
    Ok(())
}

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
fn read_f32<const N: usize>(file: &GltfFile, accessor: &gltf::Accessor) -> Option<Vec<[f32; N]>>
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

/// What an attribute is read as: `[f32; 2]`, `[f32; 3]` or `[f32; 4]`.
pub trait Vector: Sized + Copy + AsRef<[f32]> {
    fn read(file: &GltfFile, accessor: &gltf::Accessor) -> Option<Vec<Self>>;
}

macro_rules! vectors {
    ($($n:literal),*) => {$(
        impl Vector for [f32; $n] {
            fn read(file: &GltfFile, accessor: &gltf::Accessor) -> Option<Vec<Self>> {
                read_f32::<$n>(file, accessor)
            }
        }
    )*};
}
vectors!(2, 3, 4);

/// `accessor` (checked already) read whole as f32 vectors. A NaN or an
/// infinity is an error at the accessor, not a value drawn; `what` names
/// the stream in the message.
pub fn read_finite<V: Vector>(
    file: &GltfFile,
    accessor: &gltf::Accessor,
    what: &str,
) -> Result<Vec<V>, GltfError> {
    let at = format!("/accessors/{}", accessor.index());
    let values = V::read(file, accessor).ok_or_else(|| {
        file.error(
            &at,
            format!("{what} could not be read"),
            "re-export the file",
        )
    })?;
    if values
        .iter()
        .any(|v| v.as_ref().iter().any(|x| !x.is_finite()))
    {
        return Err(file.error(
            &at,
            format!("{what}: a value is not finite"),
            "re-export the file",
        ));
    }
    Ok(values)
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
