//! Opening a glTF 2.0 file: the JSON (from `.gltf` or a `.glb`'s JSON
//! chunk), the glTF schema's own checks, the extension policy, and every
//! buffer's bytes — each read bounded, never outside the file's folder.
//!
//! Everything here fails closed with a [`GltfError`] at a JSON pointer; a
//! [`GltfFile`] is a document whose every buffer is present at its declared
//! length (accessor ranges are checked where they are read, `accessors`).

use super::{GltfError, Warnings};
use base64::Engine as _;
use gltf::json;
use std::path::{Component, Path, PathBuf};

/// The largest glTF (JSON or GLB) weft opens, and the most bytes all of its
/// buffers may declare together: the front end then holds at most about
/// four times the file's size (buffers, the streams read from them, the
/// mesh files written).
pub const MAX_GLTF_BYTES: u64 = 512 << 20;

/// Extensions weft honours (docs/gltf.md has what each maps to).
pub const SUPPORTED_EXTENSIONS: &[&str] = &[
    "KHR_lights_punctual",
    "KHR_materials_variants",
    "KHR_materials_sheen",
    "KHR_materials_iridescence",
    "KHR_materials_anisotropy",
    "KHR_materials_specular",
    "KHR_materials_emissive_strength",
    "KHR_texture_transform",
    MESH_QUANTIZATION,
    GPU_INSTANCING,
];

/// The extension that lets attributes use integer components
/// (`accessors` reads them).
pub const MESH_QUANTIZATION: &str = "KHR_mesh_quantization";

/// The extension that draws a node's mesh once per instance (`instancing`).
pub const GPU_INSTANCING: &str = "EXT_mesh_gpu_instancing";

/// An opened glTF: the checked document and every buffer's bytes.
pub struct GltfFile {
    pub path: PathBuf,
    /// The folder relative URIs resolve in (and may not leave).
    pub dir: PathBuf,
    pub document: gltf::Document,
    /// Per buffer, exactly its declared `byteLength` bytes.
    pub buffers: Vec<Vec<u8>>,
    /// Every node's world matrix, worked out once when a skin first needs
    /// them ([`GltfFile::node_worlds`]).
    node_worlds: std::sync::OnceLock<Vec<Option<super::transform::Mat4>>>,
}

/// `materials[3].extensions.KHR_x` (gltf-json's path) as a JSON pointer,
/// `/materials/3/extensions/KHR_x`.
pub fn json_pointer(path: &str) -> String {
    // gltf-json appends ` = "value"` to some paths.
    let path = path.split(" = ").next().unwrap_or(path);
    let mut out = String::new();
    for part in path.split('.') {
        let (key, rest) = part.split_once('[').unwrap_or((part, ""));
        if !key.is_empty() {
            out.push('/');
            out.push_str(&key.replace('~', "~0").replace('/', "~1"));
        }
        for index in rest.split('[') {
            let index = index.trim_end_matches(']');
            if !index.is_empty() {
                out.push('/');
                out.push_str(index.trim_matches('"'));
            }
        }
    }
    if out.is_empty() { "/".into() } else { out }
}

impl GltfFile {
    /// Reads, parses and checks `path` (`.gltf` or `.glb`), and loads its buffers.
    pub fn open(path: &Path, warnings: &mut Warnings) -> Result<GltfFile, GltfError> {
        let bytes = weft_meta::files::read_regular(path, MAX_GLTF_BYTES).map_err(|e| {
            GltfError::new(
                path,
                "",
                format!("cannot read the file: {e}"),
                "give a readable .gltf or .glb file of at most 512 MiB",
            )
        })?;
        let dir = path
            .canonicalize()
            .ok()
            .and_then(|p| p.parent().map(Path::to_path_buf))
            .unwrap_or_else(|| PathBuf::from("."));
        Self::from_bytes(path, Some(&dir), bytes, warnings)
    }

    /// Parses and checks a glTF held in memory; `path` names it in
    /// messages. Relative URIs resolve in `dir` (None: in-memory, only the
    /// GLB chunk and data URIs can hold buffers).
    pub fn from_bytes(
        path: &Path,
        dir: Option<&Path>,
        bytes: Vec<u8>,
        warnings: &mut Warnings,
    ) -> Result<GltfFile, GltfError> {
        let err = |pointer: &str, message: String, hint: &str| {
            GltfError::new(path, pointer, message, hint)
        };
        if bytes.len() as u64 > MAX_GLTF_BYTES {
            return Err(err(
                "",
                format!("{} bytes; weft reads at most {MAX_GLTF_BYTES}", bytes.len()),
                "split the scene",
            ));
        }
        let (json_bytes, bin) = if bytes.starts_with(b"glTF") {
            let (json, bin) = glb_chunks(&bytes).map_err(|e| {
                err(
                    "",
                    format!("not a valid GLB container: {e}"),
                    "re-export the file; a GLB is a 12-byte header, a JSON chunk and an optional BIN chunk",
                )
            })?;
            // The BIN chunk keeps the file's own allocation (moved to its
            // front, the rest cut off): memory stays at one copy of the file.
            let json = json.to_vec();
            let bin = bin.map(|b| (b.as_ptr() as usize - bytes.as_ptr() as usize, b.len()));
            let bin = bin.map(|(start, len)| {
                let mut owned = bytes;
                owned.drain(..start);
                owned.truncate(len);
                owned
            });
            (json, bin)
        } else {
            (bytes, None)
        };
        let root: json::Root = serde_json::from_slice(&json_bytes).map_err(|e| {
            err(
                "",
                // serde_json's message already ends "at line L column C".
                format!("not glTF 2.0 JSON: {e}"),
                "weft reads glTF 2.0 (.gltf JSON or .glb binary)",
            )
        })?;
        if !root.asset.version.starts_with("2.") {
            return Err(err(
                "/asset/version",
                format!("glTF version `{}`; weft reads 2.x", root.asset.version),
                "re-export as glTF 2.0",
            ));
        }
        // Extensions first: the schema check refuses an unknown required
        // one without saying where it is used.
        check_extensions(&root, path, warnings)?;
        validate(&root, path)?;
        let document = gltf::Document::from_json_without_validation(root);
        let buffers = load_buffers(&document, path, dir, bin)?;
        Ok(GltfFile {
            path: path.to_path_buf(),
            dir: dir.map_or_else(PathBuf::new, Path::to_path_buf),
            document,
            buffers,
            node_worlds: std::sync::OnceLock::new(),
        })
    }

    /// Each node's world matrix in the file's default state
    /// ([`super::transform::world_matrices`]), computed once per file.
    pub fn node_worlds(&self) -> &[Option<super::transform::Mat4>] {
        self.node_worlds
            .get_or_init(|| super::transform::world_matrices(&self.document))
    }

    pub fn error(&self, pointer: &str, message: String, hint: &str) -> GltfError {
        GltfError::new(&self.path, pointer, message, hint)
    }
}

/// A GLB's JSON chunk and BIN chunk (glTF 2.0 § 4.4), every length checked
/// against the bytes there are (gltf 1.4's own reader underflows on some
/// lengths).
fn glb_chunks(bytes: &[u8]) -> Result<(&[u8], Option<&[u8]>), String> {
    let u32_at = |at: usize| -> Option<usize> {
        let b = bytes.get(at..at + 4)?;
        Some(u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as usize)
    };
    let version = u32_at(4).ok_or("a truncated header")?;
    if version != 2 {
        return Err(format!("GLB version {version}; weft reads 2"));
    }
    let length = u32_at(8).ok_or("a truncated header")?;
    if length > bytes.len() {
        return Err(format!(
            "the header says {length} bytes but the file has {}",
            bytes.len()
        ));
    }
    if length < 20 {
        return Err(format!(
            "the header says {length} bytes, too few for the 12-byte header and a chunk's 8-byte header"
        ));
    }
    let body = &bytes[..length];
    // A chunk at `at`: its type, its data and where the next one starts.
    type Chunk<'b> = Option<(&'b [u8], &'b [u8], usize)>;
    let chunk = |at: usize| -> Result<Chunk, String> {
        if at >= body.len() {
            return Ok(None);
        }
        let len = u32_at(at)
            .filter(|_| at + 8 <= body.len())
            .ok_or("a truncated chunk header")?;
        let data = body
            .get(at + 8..)
            .and_then(|rest| rest.get(..len))
            .ok_or_else(|| format!("a chunk of {len} bytes runs past the file"))?;
        Ok(Some((&body[at + 4..at + 8], data, at + 8 + len)))
    };
    let (kind, json, next) = chunk(12)?.ok_or("no JSON chunk")?;
    if kind != b"JSON" {
        return Err("the first chunk is not JSON".into());
    }
    let bin = match chunk(next.next_multiple_of(4))? {
        Some((kind, data, _)) if kind == b"BIN\0" => Some(data),
        _ => None,
    };
    Ok((json, bin))
}

/// The glTF schema's checks (indices in range, required fields, enums).
fn validate(root: &json::Root, path: &Path) -> Result<(), GltfError> {
    use json::validation::Validate;
    // gltf-json 1.4 indexes a primitive's POSITION accessor before checking
    // it exists (mesh.rs, `primitive_validate_hook`): checked here first.
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, prim) in mesh.primitives.iter().enumerate() {
            for (semantic, index) in &prim.attributes {
                // gltf-json keeps no name for a key it cannot read, so the
                // pointer is the attributes object.
                if *semantic == json::validation::Checked::Invalid {
                    return Err(GltfError::new(
                        path,
                        &format!("/meshes/{m}/primitives/{p}/attributes"),
                        "invalid glTF: an attribute name that is not a glTF 2.0 semantic".into(),
                        "attribute names are POSITION, NORMAL, TANGENT, TEXCOORD_n, COLOR_n, \
                         JOINTS_n and WEIGHTS_n (n a decimal number), or start with `_` \
                         (an application's own); re-export the file",
                    ));
                }
                if index.value() >= root.accessors.len() {
                    let name = match semantic {
                        json::validation::Checked::Valid(s) => s.to_string(),
                        json::validation::Checked::Invalid => "?".into(),
                    };
                    return Err(GltfError::new(
                        path,
                        &format!("/meshes/{m}/primitives/{p}/attributes/{name}"),
                        format!(
                            "invalid glTF: accessor {} does not exist ({} accessors)",
                            index.value(),
                            root.accessors.len()
                        ),
                        "the file breaks the glTF 2.0 schema; re-export it",
                    ));
                }
            }
        }
    }
    let mut first: Option<(String, String)> = None;
    let checked = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        root.validate(root, json::Path::new, &mut |p, e| {
            let pointer = json_pointer(p().as_str());
            if first.is_none() && !weft_checks_itself(&pointer, &e) {
                first = Some((pointer, e.to_string()));
            }
        })
    }));
    if checked.is_err() {
        return Err(GltfError::new(
            path,
            "",
            "invalid glTF: the schema check failed on an inconsistent file".into(),
            "run the Khronos glTF validator on the file",
        ));
    }
    match first {
        None => Ok(()),
        Some((pointer, message)) => Err(GltfError::new(
            path,
            &pointer,
            format!("invalid glTF: {message}"),
            "the file breaks the glTF 2.0 schema; re-export it or run the Khronos glTF validator",
        )),
    }
}

/// Whether a gltf-json 1.4 schema error is one weft checks in its own way.
/// - A field glTF 2.0 leaves optional, reported as missing: an accessor
///   without `bufferView` (and without `sparse`) is all zeros (§ 3.6.2.1), and
///   a texture without `source` takes its image from an extension (§ 5.29).
///   weft checks both where it reads them, with their own errors
///   (`accessors::check_accessor`, `scene::images::gltf_texture`), so a file
///   whose drawn primitives and materials do not use them opens.
/// - A required extension gltf-json does not know (`KHR_mesh_quantization`):
///   [`check_extensions`] has already refused every one weft does not honour.
fn weft_checks_itself(pointer: &str, error: &json::validation::Error) -> bool {
    use json::validation::Error;
    let parts: Vec<&str> = pointer.split('/').collect();
    matches!(
        (error, parts.as_slice()),
        (
            Error::Missing,
            ["", "accessors", _, "bufferView"] | ["", "textures", _, "source"]
        ) | (Error::Unsupported, ["", "extensionsRequired", _])
    )
}

/// Where an extension is used in the file, for the error's pointer: the
/// first material, node, texture or mesh primitive whose `extensions` name it.
fn first_use(root: &json::Root, name: &str) -> Option<String> {
    let value = serde_json::to_value(root).ok()?;
    fn walk(v: &serde_json::Value, name: &str, at: String) -> Option<String> {
        match v {
            serde_json::Value::Object(map) => {
                if let Some(serde_json::Value::Object(ext)) = map.get("extensions")
                    && ext.contains_key(name)
                {
                    return Some(format!("{at}/extensions/{name}"));
                }
                map.iter()
                    .filter(|(k, _)| k.as_str() != "extensions")
                    .find_map(|(k, v)| walk(v, name, format!("{at}/{k}")))
            }
            serde_json::Value::Array(items) => items
                .iter()
                .enumerate()
                .find_map(|(i, v)| walk(v, name, format!("{at}/{i}"))),
            _ => None,
        }
    }
    ["materials", "nodes", "textures", "meshes", "images"]
        .iter()
        .find_map(|k| walk(value.get(*k)?, name, format!("/{k}")))
}

/// Required extensions weft cannot honour fail the build; merely used ones
/// are dropped with a warning that says so.
fn check_extensions(
    root: &json::Root,
    path: &Path,
    warnings: &mut Warnings,
) -> Result<(), GltfError> {
    for (i, name) in root.extensions_required.iter().enumerate() {
        if !SUPPORTED_EXTENSIONS.contains(&name.as_str()) {
            let pointer = first_use(root, name).unwrap_or(format!("/extensionsRequired/{i}"));
            return Err(GltfError::new(
                path,
                &pointer,
                format!("the file requires extension `{name}`, which weft cannot honour"),
                &format!(
                    "weft honours {}; export without `{name}` (or only in extensionsUsed, and weft drops it with a warning)",
                    SUPPORTED_EXTENSIONS.join(", ")
                ),
            ));
        }
    }
    for name in &root.extensions_used {
        if !SUPPORTED_EXTENSIONS.contains(&name.as_str()) {
            let pointer = first_use(root, name).unwrap_or("/extensionsUsed".into());
            warnings.push(format!(
                "{}: {pointer}: extension `{name}` is not supported; weft draws without it",
                super::shown(path)
            ));
        }
    }
    Ok(())
}

/// `data:<type>;base64,<payload>`: the payload of a buffer data URI.
pub(crate) fn data_uri(uri: &str) -> Option<(&str, &str)> {
    let rest = uri.strip_prefix("data:")?;
    let (header, payload) = rest.split_once(',')?;
    let media = header.strip_suffix(";base64")?;
    Some((media, payload))
}

/// A relative URI's file, inside `dir`: percent-decoded, no absolute path,
/// no scheme, never leaving the folder (also through symbolic links).
pub fn resolve_relative_uri(dir: &Path, uri: &str) -> Result<PathBuf, String> {
    if uri.contains("://") || uri.starts_with('/') || uri.starts_with('\\') {
        return Err("only relative URIs inside the file's folder are read".into());
    }
    let bytes = uri.as_bytes();
    let mut decoded = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' && i + 2 < bytes.len() {
            let hex = std::str::from_utf8(&bytes[i + 1..i + 3]).map_err(|_| "bad %-escape")?;
            decoded.push(u8::from_str_radix(hex, 16).map_err(|_| "bad %-escape")?);
            i += 3;
        } else {
            decoded.push(bytes[i]);
            i += 1;
        }
    }
    let decoded = String::from_utf8(decoded).map_err(|_| "the URI is not UTF-8")?;
    let relative = Path::new(&decoded);
    if relative
        .components()
        .any(|c| !matches!(c, Component::Normal(_) | Component::CurDir))
    {
        return Err("the URI leaves the file's folder (`..` or an absolute path)".into());
    }
    let joined = dir.join(relative);
    let real = joined
        .canonicalize()
        .map_err(|e| format!("cannot open `{}`: {e}", joined.display()))?;
    if !real.starts_with(dir) {
        return Err(format!(
            "`{}` lies outside the file's folder (a symbolic link)",
            joined.display()
        ));
    }
    Ok(real)
}

/// Every buffer at exactly its declared length: the GLB's BIN chunk, a
/// base64 data URI or a file beside the glTF.
fn load_buffers(
    document: &gltf::Document,
    path: &Path,
    dir: Option<&Path>,
    mut bin: Option<Vec<u8>>,
) -> Result<Vec<Vec<u8>>, GltfError> {
    let declared: u64 = document.buffers().map(|b| b.length() as u64).sum();
    if declared > MAX_GLTF_BYTES {
        return Err(GltfError::new(
            path,
            "/buffers",
            format!("the buffers declare {declared} bytes; weft reads at most {MAX_GLTF_BYTES}"),
            "split the scene into several files",
        ));
    }
    let mut out = Vec::new();
    for buffer in document.buffers() {
        let pointer = format!("/buffers/{}", buffer.index());
        let err = |message: String, hint: &str| GltfError::new(path, &pointer, message, hint);
        let length = buffer.length();
        let mut bytes = match buffer.source() {
            gltf::buffer::Source::Bin => bin.take().ok_or_else(|| {
                err(
                    "a buffer without `uri` but no GLB BIN chunk holds it".into(),
                    "only the first buffer of a .glb may omit `uri`",
                )
            })?,
            gltf::buffer::Source::Uri(uri) => match data_uri(uri) {
                Some((media, payload)) => {
                    if media != "application/octet-stream" && media != "application/gltf-buffer" {
                        return Err(err(
                            format!("a buffer data URI of type `{media}`"),
                            "buffer data URIs are `data:application/octet-stream;base64,…` or `data:application/gltf-buffer;base64,…`",
                        ));
                    }
                    // base64 grows 4/3: a payload that decodes past the
                    // declared length is refused before decoding.
                    if payload.len() / 4 * 3 > length + 3 {
                        return Err(err(
                            format!("the data URI holds more than the declared {length} bytes"),
                            "the buffer's byteLength must match its data",
                        ));
                    }
                    base64::engine::general_purpose::STANDARD
                        .decode(payload)
                        .map_err(|e| {
                            err(
                                format!("bad base64 in the data URI: {e}"),
                                "re-export the file",
                            )
                        })?
                }
                None if uri.starts_with("data:") => {
                    return Err(err(
                        "a data URI that is not base64".into(),
                        "buffer data URIs are `data:application/octet-stream;base64,…`",
                    ));
                }
                None => {
                    let dir = dir.ok_or_else(|| {
                        err(
                            format!("buffer `{uri}`: an in-memory glTF cannot name files"),
                            "embed the buffer (GLB or a data URI)",
                        )
                    })?;
                    let file = resolve_relative_uri(dir, uri).map_err(|e| {
                        err(
                            format!("buffer `{uri}`: {e}"),
                            "keep buffers beside the glTF file",
                        )
                    })?;
                    weft_meta::files::read_regular(&file, length as u64 + 4).map_err(|e| {
                        err(
                            format!("cannot read buffer `{uri}`: {e}"),
                            "keep buffers beside the glTF file",
                        )
                    })?
                }
            },
        };
        if bytes.len() < length {
            return Err(err(
                format!(
                    "the buffer declares {length} bytes but holds {}: the file is truncated",
                    bytes.len()
                ),
                "re-export the file",
            ));
        }
        // A GLB's BIN chunk is padded to 4 bytes; a file may hold more.
        bytes.truncate(length);
        out.push(bytes);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pointers_from_paths() {
        assert_eq!(
            json_pointer("materials[3].extensions.KHR_materials_clearcoat"),
            "/materials/3/extensions/KHR_materials_clearcoat"
        );
        assert_eq!(
            json_pointer("meshes[0].primitives[2].attributes[\"POSITION\"]"),
            "/meshes/0/primitives/2/attributes/POSITION"
        );
        assert_eq!(json_pointer("asset"), "/asset");
    }

    /// A one-triangle file with an accessor without `bufferView` and a
    /// texture without `source` that nothing draws: valid glTF 2.0, so it
    /// opens.
    #[test]
    fn fields_gltf_2_leaves_optional_are_checked_where_read_not_up_front() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.gltf");
        // Three positions, as base64 of 9 little-endian f32.
        let data: Vec<u8> = [0f32, 0., 0., 1., 0., 0., 0., 1., 0.]
            .iter()
            .flat_map(|f| f.to_le_bytes())
            .collect();
        let uri = format!(
            "data:application/octet-stream;base64,{}",
            base64::Engine::encode(&base64::engine::general_purpose::STANDARD, &data)
        );
        let text = serde_json::json!({
            "asset": { "version": "2.0" },
            "scene": 0, "scenes": [ { "nodes": [0] } ], "nodes": [ { "mesh": 0 } ],
            "meshes": [ { "primitives": [ { "attributes": { "POSITION": 0 } } ] } ],
            "buffers": [ { "byteLength": 36, "uri": uri } ],
            "bufferViews": [ { "buffer": 0, "byteLength": 36 } ],
            "accessors": [
                { "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                  "min": [0, 0, 0], "max": [1, 1, 0] },
                { "componentType": 5126, "count": 3, "type": "VEC3" }
            ],
            "textures": [ {} ]
        });
        std::fs::write(&path, serde_json::to_vec(&text).unwrap()).unwrap();
        let mut warnings = Warnings::default();
        if let Err(e) = GltfFile::open(&path, &mut warnings) {
            panic!("{e}");
        }
        // Not optional: a texture's `sampler` out of range.
        let mut bad = text.clone();
        bad["textures"] = serde_json::json!([ { "sampler": 4 } ]);
        std::fs::write(&path, serde_json::to_vec(&bad).unwrap()).unwrap();
        let e = GltfFile::open(&path, &mut warnings)
            .err()
            .unwrap()
            .to_string();
        assert!(e.contains("at /textures/0/sampler"), "{e}");
    }

    #[test]
    fn glb_lengths_are_described_as_they_are() {
        let header = |length: u32| {
            let mut b = b"glTF".to_vec();
            b.extend(2u32.to_le_bytes());
            b.extend(length.to_le_bytes());
            b
        };
        assert_eq!(
            glb_chunks(&header(12)).unwrap_err(),
            "the header says 12 bytes, too few for the 12-byte header and a chunk's 8-byte header"
        );
        assert_eq!(
            glb_chunks(&header(40)).unwrap_err(),
            "the header says 40 bytes but the file has 12"
        );
        let mut truncated = header(24);
        truncated.extend(100u32.to_le_bytes());
        truncated.extend(b"JSON{}  ");
        assert_eq!(
            glb_chunks(&truncated).unwrap_err(),
            "a chunk of 100 bytes runs past the file"
        );
    }

    #[test]
    fn uris_stay_in_the_folder() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path().canonicalize().unwrap();
        std::fs::write(root.join("a b.bin"), b"x").unwrap();
        assert!(resolve_relative_uri(&root, "a%20b.bin").is_ok());
        for bad in ["../x.bin", "/etc/passwd", "http://x/y.bin", "sub/../../x"] {
            assert!(resolve_relative_uri(&root, bad).is_err(), "{bad}");
        }
    }
}
