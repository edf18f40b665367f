//! A glTF mesh primitive as the engine interface's six vertex streams
//! ([`MeshData`]): positions, normals (flat when the file has none, as glTF
//! requires), tangents (MikkTSpace when the file has none, as glTF
//! requires), `TEXCOORD_0/1`, `COLOR_0`, u32 indices.
//!
//! Every accessor is checked before it is read
//! ([`accessors::check_accessor`]: its type, its count and every byte range,
//! sparse parts included, inside its buffer view and buffer), so a hostile
//! file is an error at its JSON pointer, never a panic or an allocation the
//! file's own bytes do not back. The mesh is then posed as the drawing node
//! shows it ([`pose`]).

use super::GltfError;
use super::accessors::{self, Allowed, Norm, check_accessor};
use super::document::GltfFile;
use super::pose;
use super::transform::unit_or;
use gltf::accessor::{DataType, Dimensions};
use gltf::mesh::{Mode, Semantic};
use weft_meta::mesh::MeshData;

pub use super::accessors::MAX_PRIMITIVE_VERTICES;

/// What a primitive's file provides beyond positions and indices (the
/// streams weft fills in are listed apart, for the scene's vertex inputs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Provided {
    pub uv0: bool,
    pub uv1: bool,
    pub color: bool,
    /// Tangents exist: from the file, or generated (needs normals and uv0).
    pub tangent: bool,
}

/// One primitive's streams, and what they hold.
pub struct PrimitiveMesh {
    pub data: MeshData,
    pub provided: Provided,
    /// Flat normals or MikkTSpace tangents weft generated, said in the build output.
    pub generated: Vec<&'static str>,
}

const F32: DataType = DataType::F32;

/// The accessor types of each attribute weft reads: glTF 2.0 § 3.7.2.1, and
/// with `KHR_mesh_quantization` its integer types as well.
struct AttributeTypes {
    position: Vec<Allowed>,
    normal: Vec<Allowed>,
    tangent: Vec<Allowed>,
    tex_coord: Vec<Allowed>,
    color: Vec<Allowed>,
}

impl AttributeTypes {
    fn new(quantized: bool) -> AttributeTypes {
        use DataType::{I8, I16, U8, U16};
        use Dimensions::{Vec2, Vec3, Vec4};
        let mut types = AttributeTypes {
            position: vec![(F32, Vec3, Norm::Either)],
            normal: vec![(F32, Vec3, Norm::Either)],
            tangent: vec![(F32, Vec4, Norm::Either)],
            tex_coord: vec![
                (F32, Vec2, Norm::Either),
                (U8, Vec2, Norm::Yes),
                (U16, Vec2, Norm::Yes),
            ],
            color: [Vec3, Vec4]
                .into_iter()
                .flat_map(|d| {
                    [
                        (F32, d, Norm::Either),
                        (U8, d, Norm::Yes),
                        (U16, d, Norm::Yes),
                    ]
                })
                .collect(),
        };
        if quantized {
            for t in [I8, U8, I16, U16] {
                types.position.push((t, Vec3, Norm::Either));
                types.tex_coord.push((t, Vec2, Norm::Either));
            }
            for t in [I8, I16] {
                types.normal.push((t, Vec3, Norm::Yes));
                types.tangent.push((t, Vec4, Norm::Yes));
            }
        }
        types
    }
}

/// The mesh primitive `/meshes/<mesh>/primitives/<primitive>` as vertex
/// streams, posed as `node` draws it in the file's default state (its morph
/// weights, its skin: [`pose`]); without a node, with the mesh's own
/// default morph weights.
pub fn read_primitive(
    file: &GltfFile,
    mesh: usize,
    primitive: usize,
    node: Option<usize>,
) -> Result<PrimitiveMesh, GltfError> {
    let pointer = format!("/meshes/{mesh}/primitives/{primitive}");
    let gltf_mesh = file.document.meshes().nth(mesh);
    let prim = gltf_mesh
        .as_ref()
        .and_then(|m| m.primitives().nth(primitive))
        .ok_or_else(|| {
            file.error(
                &pointer,
                "no such mesh primitive".into(),
                "count meshes and primitives from 0",
            )
        })?;
    if !matches!(
        prim.mode(),
        Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
    ) {
        return Err(file.error(
            &format!("{pointer}/mode"),
            format!("primitive mode {:?}; weft draws triangles", prim.mode()),
            "export triangles (modes 4, 5 or 6); points and lines are not surfaces to shade",
        ));
    }
    let attributes = Attributes::checked(file, &prim, &pointer)?;
    let (mut data, indices) = read_streams(file, &prim, &attributes, &pointer)?;
    let node = match node {
        None => None,
        Some(n) => Some(file.document.nodes().nth(n).ok_or_else(|| {
            file.error(
                "/nodes",
                format!("the file has no node {n}"),
                "count nodes from 0",
            )
        })?),
    };
    if let Some(m) = &gltf_mesh {
        pose::morph(file, m, &prim, node.as_ref(), &mut data, &pointer)?;
    }
    if let Some(node) = node.as_ref().filter(|n| n.skin().is_some()) {
        pose::skin(file, &prim, node, file.node_worlds(), &mut data, &pointer)?;
    }
    Ok(complete_streams(data, indices, &attributes))
}

/// Which attributes the primitive has, each accessor checked (type, count,
/// byte ranges) before anything is read.
struct Attributes<'a> {
    position: gltf::Accessor<'a>,
    count: usize,
    normal: Option<gltf::Accessor<'a>>,
    tangent: Option<gltf::Accessor<'a>>,
    uv0: Option<gltf::Accessor<'a>>,
    uv1: Option<gltf::Accessor<'a>>,
    color: Option<gltf::Accessor<'a>>,
}

impl<'a> Attributes<'a> {
    fn checked(
        file: &GltfFile,
        prim: &gltf::Primitive<'a>,
        pointer: &str,
    ) -> Result<Attributes<'a>, GltfError> {
        let types = AttributeTypes::new(accessors::quantized(file));
        let get = |semantic: Semantic,
                   allowed: &[Allowed],
                   what: &str|
         -> Result<Option<gltf::Accessor>, GltfError> {
            match prim.get(&semantic) {
                None => Ok(None),
                Some(a) => {
                    check_accessor(file, &a, allowed, &format!("{pointer} {what}"))?;
                    Ok(Some(a))
                }
            }
        };
        let position = get(Semantic::Positions, &types.position, "POSITION")?.ok_or_else(|| {
            file.error(
                &format!("{pointer}/attributes"),
                "the primitive has no POSITION".into(),
                "every drawn primitive needs positions",
            )
        })?;
        let count = position.count();
        let normal = get(Semantic::Normals, &types.normal, "NORMAL")?;
        let tangent = get(Semantic::Tangents, &types.tangent, "TANGENT")?;
        let uv0 = get(Semantic::TexCoords(0), &types.tex_coord, "TEXCOORD_0")?;
        let uv1 = get(Semantic::TexCoords(1), &types.tex_coord, "TEXCOORD_1")?;
        let color = get(Semantic::Colors(0), &types.color, "COLOR_0")?;
        for (a, name) in [
            (&normal, "NORMAL"),
            (&tangent, "TANGENT"),
            (&uv0, "TEXCOORD_0"),
            (&uv1, "TEXCOORD_1"),
            (&color, "COLOR_0"),
        ] {
            if let Some(a) = a
                && a.count() != count
            {
                return Err(file.error(
                    &format!("/accessors/{}", a.index()),
                    format!("{name} has {} elements, POSITION {count}", a.count()),
                    "every attribute of a primitive has one element per vertex",
                ));
            }
        }
        if let Some(idx) = prim.indices() {
            let types = [DataType::U8, DataType::U16, DataType::U32]
                .map(|t| (t, Dimensions::Scalar, Norm::Either));
            check_accessor(file, &idx, &types, &format!("{pointer} indices"))?;
        }
        Ok(Attributes {
            position,
            count,
            normal,
            tangent,
            uv0,
            uv1,
            color,
        })
    }
}

/// The streams the file has, read (positions finite, indices a whole number
/// of triangles and in range; normals and tangents made unit length).
fn read_streams(
    file: &GltfFile,
    prim: &gltf::Primitive,
    attributes: &Attributes,
    pointer: &str,
) -> Result<(MeshData, Vec<u32>), GltfError> {
    let count = attributes.count;
    let reader = prim.reader(|b| file.buffers.get(b.index()).map(Vec::as_slice));
    let unreadable = |what: &str| {
        file.error(
            pointer,
            format!("{what} could not be read"),
            "re-export the file",
        )
    };
    // Every stream is checked finite as it is read: a NaN or an infinity
    // is an error at its accessor.
    let mut data = MeshData {
        positions: accessors::read_finite(
            file,
            &attributes.position,
            &format!("{pointer} POSITION"),
        )?,
        ..MeshData::default()
    };
    let indices: Vec<u32> = match prim.indices() {
        Some(_) => reader
            .read_indices()
            .ok_or_else(|| unreadable("indices"))?
            .into_u32()
            .collect(),
        None => (0..count as u32).collect(),
    };
    let indices = triangle_list(prim.mode(), indices);
    if indices.is_empty() && prim.mode() != Mode::Triangles {
        return Err(file.error(
            pointer,
            format!(
                "a {:?} of fewer than 3 vertices draws no triangle",
                prim.mode()
            ),
            "re-export the file",
        ));
    }
    if !indices.len().is_multiple_of(3) {
        return Err(file.error(
            pointer,
            format!(
                "{} indices is not a whole number of triangles",
                indices.len()
            ),
            "a triangle list has 3 indices per triangle",
        ));
    }
    if let Some(bad) = indices.iter().find(|&&i| i as usize >= count) {
        return Err(file.error(
            &format!("{pointer}/indices"),
            format!("index {bad} is out of range: the primitive has {count} vertices"),
            "re-export the file",
        ));
    }
    if let Some(normal) = &attributes.normal {
        data.normals =
            accessors::read_finite::<[f32; 3]>(file, normal, &format!("{pointer} NORMAL"))?
                .into_iter()
                .map(|n| unit_or(n, [0.0, 0.0, 1.0]))
                .collect();
    }
    if let Some(uv0) = &attributes.uv0 {
        data.uv0 = accessors::read_finite(file, uv0, &format!("{pointer} TEXCOORD_0"))?;
    }
    if let Some(uv1) = &attributes.uv1 {
        data.uv1 = accessors::read_finite(file, uv1, &format!("{pointer} TEXCOORD_1"))?;
    }
    if let Some(color) = &attributes.color {
        // COLOR_0 is RGB (alpha 1) or RGBA.
        let what = format!("{pointer} COLOR_0");
        data.colors = if color.dimensions() == Dimensions::Vec3 {
            accessors::read_finite::<[f32; 3]>(file, color, &what)?
                .into_iter()
                .map(|[r, g, b]| [r, g, b, 1.0])
                .collect()
        } else {
            accessors::read_finite(file, color, &what)?
        };
    }
    if let (Some(tangent), Some(_)) = (&attributes.tangent, &attributes.normal) {
        data.tangents =
            accessors::read_finite::<[f32; 4]>(file, tangent, &format!("{pointer} TANGENT"))?
                .into_iter()
                .map(|t| {
                    let [x, y, z] = unit_or([t[0], t[1], t[2]], [1.0, 0.0, 0.0]);
                    [x, y, z, if t[3] < 0.0 { -1.0 } else { 1.0 }]
                })
                .collect();
    }
    Ok((data, indices))
}

/// A strip's or a fan's triangles as a list, in glTF 2.0's order
/// (§ 3.7.2.1, "Topology"): strip triangle i is (vᵢ, vᵢ₊₁₊ᵢ﹪₂, vᵢ₊₂₋ᵢ﹪₂),
/// fan triangle i (vᵢ₊₁, vᵢ₊₂, v₀), so every triangle keeps the winding
/// of the first. A list is returned as it is.
fn triangle_list(mode: Mode, indices: Vec<u32>) -> Vec<u32> {
    let n = indices.len();
    match mode {
        Mode::TriangleStrip => (0..n.saturating_sub(2))
            .flat_map(|i| [indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]])
            .collect(),
        Mode::TriangleFan => (0..n.saturating_sub(2))
            .flat_map(|i| [indices[i + 1], indices[i + 2], indices[0]])
            .collect(),
        _ => indices,
    }
}

/// What glTF says a renderer makes when the file lacks it: flat normals
/// (one vertex per corner), MikkTSpace tangents; the other streams hold what
/// the renderer binds for them.
fn complete_streams(
    mut data: MeshData,
    mut indices: Vec<u32>,
    attributes: &Attributes,
) -> PrimitiveMesh {
    let mut generated = Vec::new();
    if attributes.normal.is_none() {
        // A file's tangents without normals are dropped: MikkTSpace redoes them.
        generated.push("flat normals (the file has none)");
        data.positions = per_corner(&data.positions, &indices);
        data.uv0 = per_corner(&data.uv0, &indices);
        data.uv1 = per_corner(&data.uv1, &indices);
        data.colors = per_corner(&data.colors, &indices);
        data.tangents.clear();
        indices = (0..indices.len() as u32).collect();
        data.normals = flat_normals(&data.positions);
    }
    if data.tangents.is_empty() {
        if attributes.uv0.is_some() {
            generated.push("MikkTSpace tangents (the file has none)");
            data.tangents = mikktspace_tangents(&data, &indices);
        } else {
            data.tangents = data.normals.iter().map(|n| any_tangent(*n)).collect();
        }
    }
    let provided = Provided {
        uv0: attributes.uv0.is_some(),
        uv1: attributes.uv1.is_some(),
        color: attributes.color.is_some(),
        tangent: attributes.tangent.is_some() || attributes.uv0.is_some(),
    };
    let v = data.positions.len();
    if data.uv0.is_empty() {
        data.uv0 = vec![[0.0; 2]; v];
    }
    if data.uv1.is_empty() {
        data.uv1 = data.uv0.clone();
    }
    if data.colors.is_empty() {
        data.colors = vec![[1.0; 4]; v];
    }
    data.indices = indices;
    PrimitiveMesh {
        data,
        provided,
        generated,
    }
}

fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// A per-vertex stream expanded to one element per triangle corner
/// (empty stays empty).
fn per_corner<T: Copy>(stream: &[T], indices: &[u32]) -> Vec<T> {
    if stream.is_empty() {
        return Vec::new();
    }
    indices.iter().map(|&i| stream[i as usize]).collect()
}

fn flat_normals(corners: &[[f32; 3]]) -> Vec<[f32; 3]> {
    corners
        .chunks_exact(3)
        .flat_map(|t| {
            let n = unit_or(cross(sub(t[1], t[0]), sub(t[2], t[0])), [0.0, 0.0, 1.0]);
            [n; 3]
        })
        .collect()
}

/// A unit tangent perpendicular to `n` where no UVs give a direction.
fn any_tangent(n: [f32; 3]) -> [f32; 4] {
    let axis = if n[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let t = unit_or(cross(axis, n), [1.0, 0.0, 0.0]);
    [t[0], t[1], t[2], 1.0]
}

struct Mikk<'a> {
    data: &'a MeshData,
    indices: &'a [u32],
    tangents: Vec<[f32; 4]>,
}

impl mikktspace::Geometry for Mikk<'_> {
    fn num_faces(&self) -> usize {
        self.indices.len() / 3
    }
    fn num_vertices_of_face(&self, _face: usize) -> usize {
        3
    }
    fn position(&self, face: usize, vert: usize) -> [f32; 3] {
        self.data.positions[self.indices[face * 3 + vert] as usize]
    }
    fn normal(&self, face: usize, vert: usize) -> [f32; 3] {
        self.data.normals[self.indices[face * 3 + vert] as usize]
    }
    fn tex_coord(&self, face: usize, vert: usize) -> [f32; 2] {
        self.data.uv0[self.indices[face * 3 + vert] as usize]
    }
    fn set_tangent_encoded(&mut self, tangent: [f32; 4], face: usize, vert: usize) {
        // Per corner; a vertex shared by corners MikkTSpace splits would
        // need its own vertex — welded corners of one vertex agree unless
        // the UVs mirror there, where the last corner wins.
        self.tangents[self.indices[face * 3 + vert] as usize] = tangent;
    }
}

/// MikkTSpace tangents (glTF 2.0 § 3.7.2.1: "When tangents are not
/// specified, client implementations SHOULD calculate tangents using
/// default MikkTSpace algorithms"), w the bitangent sign.
fn mikktspace_tangents(data: &MeshData, indices: &[u32]) -> Vec<[f32; 4]> {
    // mikktspace 0.3 sets aside triangles with two equal corner positions
    // and, when none is left, underflows a count (a panic here, memory
    // past its buffers in a release build): such a mesh has nothing to give
    // tangents to.
    let proper = indices.chunks_exact(3).any(|t| {
        let [a, b, c] = [0, 1, 2].map(|k| data.positions[t[k] as usize]);
        a != b && a != c && b != c
    });
    if !proper {
        return data.normals.iter().map(|n| any_tangent(*n)).collect();
    }
    let mut m = Mikk {
        data,
        indices,
        tangents: data.normals.iter().map(|n| any_tangent(*n)).collect(),
    };
    mikktspace::generate_tangents(&mut m);
    m.tangents
        .into_iter()
        .zip(&data.normals)
        .map(|(t, n)| {
            let xyz = unit_or([t[0], t[1], t[2]], [1.0, 0.0, 0.0]);
            if xyz == [1.0, 0.0, 0.0] && t[0] != 1.0 {
                any_tangent(*n)
            } else {
                [xyz[0], xyz[1], xyz[2], if t[3] < 0.0 { -1.0 } else { 1.0 }]
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Found by the fuzz smoke run: a primitive whose every triangle has
    /// two equal corners made mikktspace underflow; its tangents are now
    /// any unit vector perpendicular to the normal.
    #[test]
    fn tangents_of_a_mesh_without_area_are_made_without_mikktspace() {
        let data = MeshData {
            positions: vec![[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]],
            normals: vec![[0.0, 0.0, 1.0]; 3],
            uv0: vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
            ..MeshData::default()
        };
        let tangents = mikktspace_tangents(&data, &[0, 1, 2]);
        assert_eq!(tangents.len(), 3);
        for t in tangents {
            assert!((t[0] * t[0] + t[1] * t[1] + t[2] * t[2] - 1.0).abs() < 1e-6 && t[2] == 0.0);
        }
    }

    #[test]
    fn strips_and_fans_become_lists_with_the_first_triangles_winding() {
        // A quad 0-1-2-3 (counter-clockwise) as a strip 0, 1, 3, 2 and as a
        // fan 0, 1, 2, 3: both give two counter-clockwise triangles.
        assert_eq!(
            triangle_list(Mode::TriangleStrip, vec![0, 1, 3, 2]),
            [0, 1, 3, 1, 2, 3]
        );
        assert_eq!(
            triangle_list(Mode::TriangleFan, vec![0, 1, 2, 3]),
            [1, 2, 0, 2, 3, 0]
        );
        assert_eq!(
            triangle_list(Mode::TriangleStrip, vec![0, 1, 2, 3, 4]),
            [0, 1, 2, 1, 3, 2, 2, 3, 4]
        );
        assert!(triangle_list(Mode::TriangleFan, vec![0, 1]).is_empty());
        assert_eq!(triangle_list(Mode::Triangles, vec![2, 1, 0]), [2, 1, 0]);
    }
}
