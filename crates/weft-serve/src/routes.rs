//! Every path the page reads, relative to the page (so an export works
//! under any folder of a documentation site). The server answers them from
//! memory and the exporter writes the same bytes as files: nothing is read
//! from disk per request, so no request can reach outside the build.
//!
//! | path | content |
//! | --- | --- |
//! | `index.html`, `*.js`, `style.css` | the page |
//! | `sky.wgsl` | weft-render's background shader (the environment seen from the camera) |
//! | `api/library.json` | build status: generation, diagnostics, materials |
//! | `api/materials/<name>.json` | a material's metadata (measurements and the GPU model's tier costs attached: `tier_costs.rs`) |
//! | `api/files/<path>` | a generated file (`<material>/<file>`, `luts/…`) |
//! | `api/spirv/<material>/<file>.spv.txt` | a SPIR-V file disassembled |
//! | `api/environment.json`, `.bin` | the prefiltered sky cube, SH, default light |
//! | `api/environment.json?sun=x,y,z`, `.bin?sun=…` | (server only) the same with the light and the sky's sun along x,y,z, as `weft preview --light x,y,z` |
//! | `api/meshes/<sphere\|cloth\|swatch>.json`, `.bin` | built-in meshes and cameras |
//! | `api/events` | (server only) server-sent events: one `build` event per build |

use crate::assets::{self, Environment};
use crate::build::BuildStatus;
use crate::query::Query;
use serde_json::json;
use std::collections::{BTreeMap, VecDeque};
use std::sync::{Arc, Mutex, OnceLock};
use weft_runtime::SceneKind;

/// The page's files, embedded.
pub const PAGE: &[(&str, &str, &str)] = &[
    (
        "index.html",
        "text/html; charset=utf-8",
        include_str!("page/index.html"),
    ),
    (
        "style.css",
        "text/css; charset=utf-8",
        include_str!("page/style.css"),
    ),
    (
        "app.js",
        "text/javascript; charset=utf-8",
        include_str!("page/app.js"),
    ),
    (
        "panel.js",
        "text/javascript; charset=utf-8",
        include_str!("page/panel.js"),
    ),
    (
        "render.js",
        "text/javascript; charset=utf-8",
        include_str!("page/render.js"),
    ),
    (
        "bake.js",
        "text/javascript; charset=utf-8",
        include_str!("page/bake.js"),
    ),
    (
        "sky.wgsl",
        "text/plain; charset=utf-8",
        include_str!("../../weft-render/src/sky.wgsl"),
    ),
];

/// A response body.
pub enum Body {
    Static(&'static [u8]),
    Owned(Vec<u8>),
    Shared(Arc<Vec<u8>>),
}

impl Body {
    pub fn bytes(&self) -> &[u8] {
        match self {
            Body::Static(b) => b,
            Body::Owned(b) => b,
            Body::Shared(b) => b,
        }
    }
}

pub struct Reply {
    pub content_type: &'static str,
    pub body: Body,
}

/// A built-in mesh: its kind, JSON and binary.
type MeshFiles = (SceneKind, Arc<Vec<u8>>, Arc<Vec<u8>>);

/// How many recently requested sun directions keep their environment
/// (dragging the light back and forth does not recompute).
const RECENT_SUNS: usize = 8;

/// An environment being computed or computed, shared by every request for it.
type EnvSlot = Arc<OnceLock<Environment>>;

/// Engine data computed once, on first use (the prefilter takes a moment).
#[derive(Default)]
pub struct Assets {
    environment: OnceLock<Environment>,
    meshes: OnceLock<Vec<MeshFiles>>,
    /// Environments of recently requested sun directions (normalised f32
    /// bits), most recent first.
    recent: Mutex<VecDeque<([u32; 3], EnvSlot)>>,
    /// One sun-direction prefilter at a time (the machine's cores are few;
    /// two at once would only slow each other down).
    computing: Mutex<()>,
}

impl Assets {
    pub fn environment(&self) -> &Environment {
        self.environment.get_or_init(assets::environment)
    }

    /// The environment with the sun (and the light) along `sun` (a unit
    /// vector, see [`Query::sun`]), from the cache of recent directions or
    /// computed now. Concurrent requests for one direction share one
    /// computation.
    pub fn environment_towards(&self, sun: [f32; 3]) -> EnvSlot {
        let key = sun.map(f32::to_bits);
        let slot = {
            let mut recent = match self.recent.lock() {
                Ok(r) => r,
                Err(poisoned) => poisoned.into_inner(),
            };
            let slot = match recent.iter().position(|(k, _)| *k == key) {
                Some(i) => recent.remove(i).map(|(_, s)| s).unwrap_or_default(),
                None => EnvSlot::default(),
            };
            recent.push_front((key, slot.clone()));
            recent.truncate(RECENT_SUNS);
            slot
        };
        if slot.get().is_none() {
            let _one_at_a_time = match self.computing.lock() {
                Ok(g) => g,
                Err(poisoned) => poisoned.into_inner(),
            };
            slot.get_or_init(|| assets::environment_for(Some(sun)));
        }
        slot
    }

    fn meshes(&self) -> &[MeshFiles] {
        self.meshes.get_or_init(|| {
            SceneKind::ALL
                .iter()
                .map(|&k| {
                    let (j, b) = assets::mesh(k);
                    (k, Arc::new(j), Arc::new(b))
                })
                .collect()
        })
    }
}

fn content_type(path: &str) -> &'static str {
    match path.rsplit('.').next().unwrap_or("") {
        "json" => "application/json",
        "wgsl" | "hlsl" | "glsl" | "metal" | "txt" => "text/plain; charset=utf-8",
        _ => "application/octet-stream",
    }
}

/// `api/library.json`.
pub fn library_json(status: &BuildStatus, live: bool) -> Vec<u8> {
    let materials: Vec<_> = status
        .snapshot
        .iter()
        .flat_map(|s| s.materials.iter())
        .map(|m| {
            json!({
                "name": m.metadata.name,
                "label": m.metadata.label,
                "description": m.metadata.description,
                "variants": m.metadata.variants.len(),
            })
        })
        .collect();
    let v = json!({
        "live": live,
        "generation": if live { status.generation } else { 1 },
        "ok": status.error.is_none(),
        "error": status.error,
        "warnings": status.warnings,
        "build_ms": if live { status.build_ms } else { 0 },
        "materials": materials,
    });
    serde_json::to_vec(&v).unwrap_or_default()
}

/// Why a path has no reply.
#[derive(Debug, PartialEq)]
pub enum RouteError {
    /// 404.
    NotFound,
    /// 400, with what is wrong with the request.
    BadRequest(String),
}

/// The reply for `path` (no leading slash) and its `query` (the part after
/// `?`, empty when none). A malformed query is a 400 on every path.
pub fn route(
    path: &str,
    query: &str,
    status: &BuildStatus,
    assets: &Assets,
    live: bool,
) -> Result<Reply, RouteError> {
    let query = Query::parse(query).map_err(RouteError::BadRequest)?;
    if let Some(which) = path.strip_prefix("api/environment.")
        && let Some(sun) = query.sun().map_err(RouteError::BadRequest)?
    {
        let slot = assets.environment_towards(sun);
        let env = slot.get().ok_or(RouteError::NotFound)?;
        return match which {
            "json" => Ok(Reply {
                content_type: "application/json",
                body: Body::Shared(env.json.clone()),
            }),
            "bin" => Ok(Reply {
                content_type: "application/octet-stream",
                body: Body::Shared(env.bin.clone()),
            }),
            _ => Err(RouteError::NotFound),
        };
    }
    route_plain(path, status, assets, live).ok_or(RouteError::NotFound)
}

/// The reply for `path` without a query, or None (404).
fn route_plain(path: &str, status: &BuildStatus, assets: &Assets, live: bool) -> Option<Reply> {
    let path = if path.is_empty() { "index.html" } else { path };
    if let Some((_, ct, text)) = PAGE.iter().find(|(p, _, _)| *p == path) {
        return Some(Reply {
            content_type: ct,
            body: Body::Static(text.as_bytes()),
        });
    }
    let api = path.strip_prefix("api/")?;
    let owned = |content_type, bytes| {
        Some(Reply {
            content_type,
            body: Body::Owned(bytes),
        })
    };
    let shared = |content_type, bytes: &Arc<Vec<u8>>| {
        Some(Reply {
            content_type,
            body: Body::Shared(bytes.clone()),
        })
    };
    match api {
        "library.json" => return owned("application/json", library_json(status, live)),
        "environment.json" => return shared("application/json", &assets.environment().json),
        "environment.bin" => {
            return shared("application/octet-stream", &assets.environment().bin);
        }
        _ => {}
    }
    if let Some(rest) = api.strip_prefix("meshes/") {
        let (name, ext) = rest.rsplit_once('.')?;
        let (_, j, b) = assets.meshes().iter().find(|(k, _, _)| k.name() == name)?;
        return match ext {
            "json" => shared("application/json", j),
            "bin" => shared("application/octet-stream", b),
            _ => None,
        };
    }
    let snapshot = status.snapshot.as_ref()?;
    if let Some(rest) = api.strip_prefix("materials/") {
        let name = rest.strip_suffix(".json")?;
        return owned("application/json", snapshot.material(name)?.json.clone());
    }
    if let Some(rest) = api.strip_prefix("files/") {
        let bytes = snapshot.files.get(rest)?;
        return owned(content_type(rest), bytes.clone());
    }
    if let Some(rest) = api.strip_prefix("spirv/") {
        let file = rest.strip_suffix(".txt")?;
        if !file.ends_with(".spv") {
            return None;
        }
        return shared("text/plain; charset=utf-8", &snapshot.disassembly(file)?);
    }
    None
}

/// Every static path an export writes, with its bytes (no `api/events`:
/// the page sees `live: false` and does not subscribe).
pub fn export_files(snapshot: &crate::Snapshot, status: &BuildStatus) -> BTreeMap<String, Vec<u8>> {
    let assets = Assets::default();
    let mut paths: Vec<String> = PAGE.iter().map(|(p, _, _)| p.to_string()).collect();
    paths.extend(
        [
            "api/library.json",
            "api/environment.json",
            "api/environment.bin",
        ]
        .map(String::from),
    );
    for k in SceneKind::ALL {
        paths.push(format!("api/meshes/{}.json", k.name()));
        paths.push(format!("api/meshes/{}.bin", k.name()));
    }
    for m in &snapshot.materials {
        paths.push(format!("api/materials/{}.json", m.metadata.name));
    }
    for f in snapshot.files.keys() {
        paths.push(format!("api/files/{f}"));
        if f.ends_with(".spv") {
            paths.push(format!("api/spirv/{f}.txt"));
        }
    }
    let mut out = BTreeMap::new();
    for p in paths {
        if let Ok(reply) = route(&p, "", status, &assets, false) {
            out.insert(p, reply.body.bytes().to_vec());
        }
    }
    out
}
