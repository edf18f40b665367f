//! The versioning rule of weft's metadata files, and the readers that apply it.
//!
//! A metadata file states a schema version `major.minor`: `schema_version` is
//! the major, `schema_minor` the minor (absent in files written before the
//! minor existed: read as 0).
//!
//! - **Minor**: bumped when optional fields or objects are *added* (at any
//!   depth). A reader ignores fields it does not know, so a reader built for
//!   `4.1` reads a `4.7` file — and a `4.0` one: what a minor adds is optional.
//! - **Major**: bumped when a field is removed or renamed, changes meaning or
//!   type, becomes required, or an enumerated field (`kind`, `blend`, …) gains
//!   a value. A reader rejects any other major with an error naming both
//!   versions, before it looks at anything else in the file.
//!
//! docs/engine-interface.md states the same rule for engine authors.

use crate::scene::{SCENE_SCHEMA_MINOR, SCENE_SCHEMA_VERSION, SceneMetadata};
use crate::{MaterialMetadata, SCHEMA_MINOR, SCHEMA_VERSION};
use serde::Deserialize;
use serde::de::DeserializeOwned;
use std::fmt;

/// Why a metadata file could not be read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MetaError {
    /// The file's major schema version is not the one this reader knows.
    Version {
        /// `material metadata` or `scene metadata`.
        what: &'static str,
        /// The file's `(schema_version, schema_minor)`.
        file: (u32, u32),
        /// This reader's `(major, minor)`.
        reader: (u32, u32),
    },
    /// Not JSON, no `schema_version`, or a known field of the wrong shape.
    Json {
        /// `material metadata` or `scene metadata`.
        what: &'static str,
        /// serde_json's message, with line and column.
        message: String,
    },
}

impl fmt::Display for MetaError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MetaError::Version { what, file, reader } => {
                let advice = if file.0 > reader.0 {
                    "it is newer: upgrade the weft-meta crate this engine links"
                } else {
                    "it is older: rebuild it with a weft that writes this major version"
                };
                write!(
                    f,
                    "{what} schema version {}.{} cannot be read by this reader, which reads \
                     schema version {}.{} (any {}.x); {advice}",
                    file.0, file.1, reader.0, reader.1, reader.0
                )
            }
            MetaError::Json { what, message } => write!(f, "not weft {what}: {message}"),
        }
    }
}

impl std::error::Error for MetaError {}

/// What is read first: only the version, so a file of another major is
/// named as such rather than failing on whatever field changed.
#[derive(Deserialize)]
struct Version {
    schema_version: u32,
    #[serde(default)]
    schema_minor: u32,
}

fn read<T: DeserializeOwned>(
    json: &str,
    what: &'static str,
    reader: (u32, u32),
) -> Result<T, MetaError> {
    let json_err = |e: serde_json::Error| MetaError::Json {
        what,
        message: e.to_string(),
    };
    let v: Version = serde_json::from_str(json).map_err(json_err)?;
    if v.schema_version != reader.0 {
        return Err(MetaError::Version {
            what,
            file: (v.schema_version, v.schema_minor),
            reader,
        });
    }
    serde_json::from_str(json).map_err(json_err)
}

impl MaterialMetadata {
    /// Reads `<material>.meta.json` under the versioning rule: fields this
    /// crate does not know are ignored; another major schema version is an
    /// error naming both versions.
    pub fn from_json(json: &str) -> Result<MaterialMetadata, MetaError> {
        read(json, "material metadata", (SCHEMA_VERSION, SCHEMA_MINOR))
    }
}

impl SceneMetadata {
    /// Reads `<scene>.scene.json` under the versioning rule of
    /// [`MaterialMetadata::from_json`], with the scene schema's versions.
    pub fn from_json(json: &str) -> Result<SceneMetadata, MetaError> {
        read(
            json,
            "scene metadata",
            (SCENE_SCHEMA_VERSION, SCENE_SCHEMA_MINOR),
        )
    }
}
