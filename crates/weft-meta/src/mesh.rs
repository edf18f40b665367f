//! The built-in meshes as files: `<library root>/meshes/<name>.mesh`, the
//! exact vertex data weft's renderer draws for each of
//! [`crate::BUILTIN_MESHES`] (`cargo xtask regenerate` writes them into
//! `generated/meshes/`; scene metadata names them in `meshes`). The layout
//! ([`MESH_FORMAT`], docs/engine-interface.md "Built-in meshes"), all little-endian:
//!
//! | bytes | content |
//! | --- | --- |
//! | 8 | magic `WEFTMESH` |
//! | 4 | u32 layout version, 1 |
//! | 4 | u32 vertex count V |
//! | 4 | u32 index count I (a multiple of 3: a triangle list, counter-clockwise fronts) |
//! | 4 | u32 stream count, 6 |
//! | V × 12 | position, float32x3 (location 0) |
//! | V × 12 | normal, float32x3 (location 1) |
//! | V × 16 | tangent, float32x4 (location 2; `conventions.tangent_frame`) |
//! | V × 8 | uv0, float32x2 (location 3) |
//! | V × 8 | uv1, float32x2 (location 4) |
//! | V × 16 | color, float32x4 (location 5) |
//! | I × 4 | u32 indices |
//!
//! Each stream is what one vertex buffer of the engine interface holds
//! ([`crate::VERTEX_INPUTS`], in location order): bind the ones a shader's
//! `vertex_inputs` lists.

/// The layout's name in metadata (`meshes.<name>.format`).
pub const MESH_FORMAT: &str = "weft_mesh_v1";
/// The file's first 8 bytes.
pub const MESH_MAGIC: [u8; 8] = *b"WEFTMESH";
/// The layout version in the header.
pub const MESH_LAYOUT_VERSION: u32 = 1;
const HEADER_BYTES: usize = 24;

/// Where a built-in mesh's file lives, relative to the library root.
pub fn mesh_path(name: &str) -> String {
    format!("meshes/{name}.mesh")
}

/// A triangle mesh: the engine interface's six vertex streams and the
/// indices, as a mesh file holds them. One type for every mesh weft reads,
/// draws and writes (`weft_runtime::Mesh` is this type, with the generated
/// meshes beside it; the glTF front end fills it). A file holds every stream;
/// a mesh being drawn may leave `uv1` (read as uv0) and `colors` (white)
/// empty.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    pub positions: Vec<[f32; 3]>,
    pub normals: Vec<[f32; 3]>,
    /// xyz: unit tangent along increasing u; w: bitangent sign (+1 or -1).
    pub tangents: Vec<[f32; 4]>,
    pub uv0: Vec<[f32; 2]>,
    pub uv1: Vec<[f32; 2]>,
    pub colors: Vec<[f32; 4]>,
    /// A triangle list, counter-clockwise fronts.
    pub indices: Vec<u32>,
}

fn push<const N: usize>(out: &mut Vec<u8>, values: &[[f32; N]]) {
    for v in values {
        for c in v {
            out.extend(c.to_le_bytes());
        }
    }
}

impl MeshData {
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// The largest distance of a vertex from the origin, rounded up to
    /// 6 decimals (what scene metadata's `meshes[].radius` states).
    pub fn radius(&self) -> f64 {
        let r = self
            .positions
            .iter()
            .map(|p| {
                p.iter()
                    .map(|&x| (x as f64) * (x as f64))
                    .sum::<f64>()
                    .sqrt()
            })
            .fold(0.0f64, f64::max);
        (r * 1e6).ceil() / 1e6
    }

    /// The file's bytes. Panics if a stream's length is not the vertex
    /// count or the index count is not a multiple of 3.
    pub fn to_bytes(&self) -> Vec<u8> {
        let v = self.vertex_count();
        for (name, len) in [
            ("normals", self.normals.len()),
            ("tangents", self.tangents.len()),
            ("uv0", self.uv0.len()),
            ("uv1", self.uv1.len()),
            ("colors", self.colors.len()),
        ] {
            assert_eq!(len, v, "{name}: one per vertex");
        }
        assert!(self.indices.len().is_multiple_of(3), "a triangle list");
        let mut out = Vec::with_capacity(HEADER_BYTES + v * 72 + self.indices.len() * 4);
        out.extend(MESH_MAGIC);
        for n in [
            MESH_LAYOUT_VERSION,
            v as u32,
            self.indices.len() as u32,
            crate::VERTEX_INPUTS.len() as u32,
        ] {
            out.extend(n.to_le_bytes());
        }
        push(&mut out, &self.positions);
        push(&mut out, &self.normals);
        push(&mut out, &self.tangents);
        push(&mut out, &self.uv0);
        push(&mut out, &self.uv1);
        push(&mut out, &self.colors);
        for i in &self.indices {
            out.extend(i.to_le_bytes());
        }
        out
    }

    /// Reads a mesh file: the header checked, every stream and index read,
    /// indices in range.
    pub fn from_bytes(bytes: &[u8]) -> Result<MeshData, String> {
        if bytes.len() < HEADER_BYTES || bytes[..8] != MESH_MAGIC {
            return Err("not a weft mesh file (no `WEFTMESH` header)".into());
        }
        let u32_at = |o: usize| u32::from_le_bytes(bytes[o..o + 4].try_into().expect("4 bytes"));
        let (version, v, i, streams) = (u32_at(8), u32_at(12), u32_at(16), u32_at(20));
        if version != MESH_LAYOUT_VERSION || streams as usize != crate::VERTEX_INPUTS.len() {
            return Err(format!(
                "mesh layout version {version} with {streams} streams; this reader reads \
                 version {MESH_LAYOUT_VERSION} with {}",
                crate::VERTEX_INPUTS.len()
            ));
        }
        let (v, i) = (v as usize, i as usize);
        let want = HEADER_BYTES + v * 72 + i * 4;
        if bytes.len() != want || !i.is_multiple_of(3) {
            return Err(format!(
                "{} bytes, but {v} vertices and {i} indices need {want}",
                bytes.len()
            ));
        }
        let mut at = HEADER_BYTES;
        let mut floats = |count: usize| -> Vec<f32> {
            let out = bytes[at..at + count * 4]
                .chunks_exact(4)
                .map(|c| f32::from_le_bytes(c.try_into().expect("4 bytes")))
                .collect();
            at += count * 4;
            out
        };
        fn group<const N: usize>(f: Vec<f32>) -> Vec<[f32; N]> {
            f.chunks_exact(N)
                .map(|c| c.try_into().expect("N floats"))
                .collect()
        }
        let mesh = MeshData {
            positions: group(floats(v * 3)),
            normals: group(floats(v * 3)),
            tangents: group(floats(v * 4)),
            uv0: group(floats(v * 2)),
            uv1: group(floats(v * 2)),
            colors: group(floats(v * 4)),
            indices: bytes[HEADER_BYTES + v * 72..]
                .chunks_exact(4)
                .map(|c| u32::from_le_bytes(c.try_into().expect("4 bytes")))
                .collect(),
        };
        if let Some(bad) = mesh.indices.iter().find(|&&x| x as usize >= v) {
            return Err(format!("index {bad} is out of range ({v} vertices)"));
        }
        Ok(mesh)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mesh_files_round_trip_and_refuse_what_is_not_one() {
        let m = MeshData {
            positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            normals: vec![[0.0, 0.0, 1.0]; 3],
            tangents: vec![[1.0, 0.0, 0.0, 1.0]; 3],
            uv0: vec![[0.0, 1.0], [1.0, 1.0], [0.0, 0.0]],
            uv1: vec![[0.0, 1.0], [1.0, 1.0], [0.0, 0.0]],
            colors: vec![[1.0; 4]; 3],
            indices: vec![0, 1, 2],
        };
        let bytes = m.to_bytes();
        assert_eq!(bytes.len(), 24 + 3 * 72 + 12);
        assert_eq!(&bytes[..8], b"WEFTMESH");
        assert_eq!(MeshData::from_bytes(&bytes).unwrap(), m);
        assert!(MeshData::from_bytes(&bytes[..bytes.len() - 1]).is_err());
        assert!(MeshData::from_bytes(b"not a mesh at all, really").is_err());
        let mut bad = bytes.clone();
        let last = bad.len() - 4;
        bad[last..].copy_from_slice(&7u32.to_le_bytes());
        assert!(
            MeshData::from_bytes(&bad)
                .unwrap_err()
                .contains("out of range")
        );
        assert_eq!(mesh_path("bust.head"), "meshes/bust.head.mesh");
    }
}
