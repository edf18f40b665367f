//! glTF 2.0 as a scene source (docs/gltf.md).
//!
//! Pipeline, data flowing one way:
//! [`document`] (the file opened and checked: schema, extension policy,
//! buffers bounded and inside the file's folder) → [`scene`] (nodes, camera,
//! lights and [`materials`] mapped into scene manifest text) → the ordinary
//! scene front end (`scene::parse`, `scene::resolve`), which reads each
//! instance's `mesh = { gltf = …, mesh = …, primitive = … }` through
//! [`meshes`] (accessors checked and read as f32 by [`accessors`],
//! `KHR_mesh_quantization`'s integer types included; normals and MikkTSpace
//! tangents generated where the file has none).
//!
//! Every problem with the file is a [`GltfError`] naming the file and the
//! JSON pointer of what is wrong, with a hint.

pub mod accessors;
pub mod document;
pub mod instancing;
pub mod materials;
pub mod meshes;
pub mod pose;
pub mod scene;
pub mod transform;

pub use document::GltfFile;
pub use meshes::{PrimitiveMesh, Provided};

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Warnings for the build output: what the file asks that weft drops.
pub type Warnings = Vec<String>;

/// A problem with a glTF file, at a JSON pointer.
#[derive(Clone, Debug, PartialEq)]
pub struct GltfError {
    pub file: PathBuf,
    /// RFC 6901 JSON pointer into the glTF JSON (`""`: the whole file).
    pub pointer: String,
    pub message: String,
    pub hint: String,
}

impl GltfError {
    pub fn new(file: &Path, pointer: &str, message: String, hint: &str) -> GltfError {
        GltfError {
            file: file.to_path_buf(),
            pointer: pointer.to_string(),
            message,
            hint: hint.to_string(),
        }
    }
}

impl std::fmt::Display for GltfError {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let at = if self.pointer.is_empty() {
            String::new()
        } else {
            format!(" at {}", self.pointer)
        };
        write!(f, "{}{at}: {}", shown(&self.file), self.message)
    }
}

/// A path as messages show it: relative to the working directory when
/// inside it.
pub fn shown(path: &Path) -> String {
    let abs = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
    crate::includes::display_path(&abs)
}

/// Whether a path names a glTF file (`.gltf` or `.glb`).
pub fn is_gltf_path(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("gltf") || e.eq_ignore_ascii_case("glb"))
}

/// A primitive read from a glTF file, named for the scene metadata.
#[derive(Debug)]
pub struct FileMesh {
    /// `<file stem>.mesh<m>.p<p>`: the key of the scene metadata's `meshes`
    /// and the file `meshes/<name>.mesh` in the scene folder.
    pub name: String,
    /// The primitive as the scene folder carries it (`weft_mesh_v1`): the
    /// one copy a build holds (docs/gltf.md "Speed and memory"); [`Self::data`]
    /// reads it back where the streams are needed (`auto` tiers, previews).
    pub bytes: Vec<u8>,
    /// The mesh's bounding radius about its origin (scene metadata `meshes.<name>.radius`).
    pub radius: f64,
    pub provided: Provided,
    pub generated: Vec<&'static str>,
}

impl FileMesh {
    /// The vertex streams, read back from [`Self::bytes`].
    pub fn data(&self) -> weft_meta::mesh::MeshData {
        weft_meta::mesh::MeshData::from_bytes(&self.bytes).expect("bytes weft serialised")
    }
}

/// A primitive read once per scene: file, mesh, primitive, uv transform (bits).
type MeshKey = (PathBuf, usize, usize, Option<[u64; 6]>, Option<usize>);

/// Eight hex digits naming a uv transform in a mesh's name (the first of
/// the SHA-256 of its bits: stable on every machine).
fn transform_hash(t: &[f64; 6]) -> String {
    use sha2::Digest;
    let bytes: Vec<u8> = t.iter().flat_map(|x| x.to_bits().to_le_bytes()).collect();
    sha2::Sha256::digest(&bytes)[..4]
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// Opened files and read primitives, each once per scene.
#[derive(Default)]
pub struct GltfCache {
    files: BTreeMap<PathBuf, Result<Arc<GltfFile>, GltfError>>,
    meshes: BTreeMap<MeshKey, Arc<FileMesh>>,
    pub warnings: Warnings,
}

impl GltfCache {
    /// A cache holding `file` already opened (so the resolver reads its
    /// meshes and images without opening it again).
    pub fn with_file(file: Arc<GltfFile>) -> GltfCache {
        let key = file
            .path
            .canonicalize()
            .unwrap_or_else(|_| file.path.clone());
        GltfCache {
            files: BTreeMap::from([(key, Ok(file))]),
            ..GltfCache::default()
        }
    }

    pub fn file(&mut self, path: &Path) -> Result<Arc<GltfFile>, GltfError> {
        let key = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
        if let Some(f) = self.files.get(&key) {
            return f.clone();
        }
        let opened = GltfFile::open(path, &mut self.warnings).map(Arc::new);
        self.files.insert(key, opened.clone());
        opened
    }

    /// Primitive `primitive` of mesh `mesh` in `path`, its TEXCOORD_0 taken
    /// through `uv_transform` ([`MeshSpec::Gltf`](crate::scene::model::MeshSpec)'s)
    /// when given — after tangents are generated from the file's own UVs, as
    /// a glTF viewer generates them — and named for it (`….uv<hash>`).
    pub fn mesh(
        &mut self,
        path: &Path,
        mesh: usize,
        primitive: usize,
        uv_transform: Option<[f64; 6]>,
        node: Option<usize>,
    ) -> Result<Arc<FileMesh>, GltfError> {
        let file = self.file(path)?;
        let key = (
            file.path
                .canonicalize()
                .unwrap_or_else(|_| file.path.clone()),
            mesh,
            primitive,
            uv_transform.map(|t| t.map(f64::to_bits)),
            node,
        );
        if let Some(m) = self.meshes.get(&key) {
            return Ok(m.clone());
        }
        let mut read = meshes::read_primitive(&file, mesh, primitive, node)?;
        let stem = scene::snake_name(
            &path
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default(),
            "gltf",
        );
        let mut name = format!("{stem}.mesh{mesh}.p{primitive}");
        if let Some(n) = node {
            name.push_str(&format!(".n{n}"));
        }
        if let Some(t) = uv_transform {
            for uv in &mut read.data.uv0 {
                let (u, v) = (f64::from(uv[0]), f64::from(uv[1]));
                *uv = [
                    (t[0] * u + t[1] * v + t[2]) as f32,
                    (t[3] * u + t[4] * v + t[5]) as f32,
                ];
            }
            name.push_str(&format!(".uv{}", transform_hash(&t)));
        }
        let m = Arc::new(FileMesh {
            name,
            radius: read.data.radius(),
            bytes: read.data.to_bytes(),
            provided: read.provided,
            generated: read.generated,
        });
        self.meshes.insert(key, m.clone());
        Ok(m)
    }
}
