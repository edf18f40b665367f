//! The built-in meshes as files (`weft_meta::mesh`): for each name of
//! `weft_meta::BUILTIN_MESHES`, the vertex streams exactly as
//! [`crate::resources`] uploads them (defaults filled in: uv1 from uv0,
//! white colours) and the indices. `cargo xtask regenerate` writes them into
//! `generated/meshes/`.

use crate::Error;
use crate::error::Result;
use crate::resources::vertex_stream;
use crate::scene::{Mesh, Scene, SceneKind};
use std::collections::BTreeMap;
use weft_meta::mesh::{MeshData, mesh_path};
use weft_meta::{VERTEX_INPUTS, VertexInput};

fn floats<const N: usize>(bytes: &[u8]) -> Vec<[f32; N]> {
    bytes
        .chunks_exact(4 * N)
        .map(|c| {
            std::array::from_fn(|i| f32::from_le_bytes(c[4 * i..4 * i + 4].try_into().unwrap()))
        })
        .collect()
}

/// A scene's mesh file (`meshes[name].file`, relative to the scene
/// folder `dir`): read, bounded, checked (indices in range).
pub fn read_scene_mesh(dir: &std::path::Path, file: &str) -> Result<Mesh> {
    let path = dir.join(file);
    let bytes = weft_meta::files::read_regular(&path, weft_meta::files::MAX_BINARY_BYTES)
        .map_err(|e| Error::Metadata(format!("mesh file `{}`: {e}", path.display())))?;
    // `from_bytes` checks the header, the lengths and every index.
    MeshData::from_bytes(&bytes)
        .map_err(|e| Error::Metadata(format!("mesh file `{}`: {e}", path.display())))
}

/// A mesh's streams as the renderer uploads them, one per engine-interface
/// vertex input.
pub fn mesh_data(mesh: &Mesh) -> Result<MeshData> {
    let stream = |location: usize| -> Result<Vec<u8>> {
        let (name, format) = VERTEX_INPUTS[location];
        vertex_stream(
            mesh,
            &VertexInput {
                name: name.into(),
                location: location as u32,
                format: format.into(),
            },
        )
    };
    Ok(MeshData {
        positions: floats(&stream(0)?),
        normals: floats(&stream(1)?),
        tangents: floats(&stream(2)?),
        uv0: floats(&stream(3)?),
        uv1: floats(&stream(4)?),
        colors: floats(&stream(5)?),
        indices: mesh.indices.clone(),
    })
}

/// `meshes/<name>.mesh` → bytes, for every built-in mesh.
pub fn builtin_mesh_files() -> Result<BTreeMap<String, Vec<u8>>> {
    SceneKind::ALL
        .into_iter()
        .map(|kind| {
            let data = mesh_data(&Scene::new(kind).mesh)?;
            Ok((mesh_path(kind.name()), data.to_bytes()))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every file in `generated/meshes/` is what the renderer draws for its
    /// mesh: each vertex stream byte for byte what `GpuMesh::upload` puts in
    /// the vertex buffer of that input, and the same indices.
    #[test]
    fn generated_mesh_files_are_what_the_renderer_draws() {
        let generated = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../generated");
        assert_eq!(SceneKind::ALL.len(), weft_meta::BUILTIN_MESHES.len());
        for kind in SceneKind::ALL {
            let path = generated.join(mesh_path(kind.name()));
            let bytes = std::fs::read(&path).unwrap_or_else(|e| {
                panic!("{}: {e}; run `cargo xtask regenerate`", path.display())
            });
            let file = MeshData::from_bytes(&bytes).unwrap();
            let mesh = Scene::new(kind).mesh;
            for (location, (name, format)) in VERTEX_INPUTS.iter().enumerate() {
                let drawn = vertex_stream(
                    &mesh,
                    &VertexInput {
                        name: (*name).into(),
                        location: location as u32,
                        format: (*format).into(),
                    },
                )
                .unwrap();
                let stored: Vec<u8> = match location {
                    0 => file
                        .positions
                        .iter()
                        .flatten()
                        .flat_map(|c| c.to_le_bytes())
                        .collect(),
                    1 => file
                        .normals
                        .iter()
                        .flatten()
                        .flat_map(|c| c.to_le_bytes())
                        .collect(),
                    2 => file
                        .tangents
                        .iter()
                        .flatten()
                        .flat_map(|c| c.to_le_bytes())
                        .collect(),
                    3 => file
                        .uv0
                        .iter()
                        .flatten()
                        .flat_map(|c| c.to_le_bytes())
                        .collect(),
                    4 => file
                        .uv1
                        .iter()
                        .flatten()
                        .flat_map(|c| c.to_le_bytes())
                        .collect(),
                    _ => file
                        .colors
                        .iter()
                        .flatten()
                        .flat_map(|c| c.to_le_bytes())
                        .collect(),
                };
                assert!(stored == drawn, "{}: stream {name} differs", kind.name());
            }
            assert_eq!(file.indices, mesh.indices, "{}: indices", kind.name());
            // What docs/engine-interface.md says of every built-in mesh.
            assert_eq!(file.uv1, file.uv0, "{}: uv1 is uv0", kind.name());
            assert!(
                file.colors.iter().all(|c| *c == [1.0; 4]),
                "{}: white",
                kind.name()
            );
            assert!(file.indices.len().is_multiple_of(3) && !file.indices.is_empty());
        }
    }
}
