//! The runtime's error type.

use std::fmt;

/// Install hint shown whenever no Vulkan adapter can be found.
pub const NO_ADAPTER_HINT: &str = "no Vulkan adapter found: weft-render needs a Vulkan driver; \
on Debian/Ubuntu install lavapipe with `apt-get install mesa-vulkan-drivers libvulkan1`";

/// Everything that can go wrong loading, configuring or drawing a material.
#[derive(Debug)]
pub enum Error {
    /// No Vulkan adapter (the message says to install `mesa-vulkan-drivers`).
    NoAdapter(String),
    /// A parameter name the material does not declare.
    UnknownParameter { name: String, valid: Vec<String> },
    /// A keyword name or value, tier, preset or variant the material does not have.
    UnknownName {
        what: &'static str,
        name: String,
        valid: Vec<String>,
    },
    /// A value of the wrong type or outside the declared range.
    InvalidValue { name: String, message: String },
    /// A file could not be read or written.
    Io {
        path: std::path::PathBuf,
        source: std::io::Error,
    },
    /// Metadata that does not parse or does not fit the engine interface.
    Metadata(String),
    /// wgpu reported an error (device creation, shader, pipeline, readback).
    Gpu(String),
    /// An error loading or drawing a scene: the scene file and, when one is
    /// to blame, the instance.
    Scene {
        file: std::path::PathBuf,
        instance: Option<String>,
        source: Box<Error>,
    },
}

pub type Result<T> = std::result::Result<T, Error>;

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::NoAdapter(detail) => {
                write!(f, "{NO_ADAPTER_HINT}")?;
                if !detail.is_empty() {
                    write!(f, " ({detail})")?;
                }
                Ok(())
            }
            Error::UnknownParameter { name, valid } => write!(
                f,
                "unknown parameter `{name}`; valid parameters: {}",
                valid.join(", ")
            ),
            Error::UnknownName { what, name, valid } => {
                write!(f, "unknown {what} `{name}`; valid: {}", valid.join(", "))
            }
            Error::InvalidValue { name, message } => write!(f, "`{name}`: {message}"),
            Error::Io { path, source } => write!(f, "{}: {source}", path.display()),
            Error::Metadata(m) => write!(f, "metadata: {m}"),
            Error::Gpu(m) => write!(f, "gpu: {m}"),
            Error::Scene {
                file,
                instance,
                source,
            } => {
                write!(f, "{}: ", file.display())?;
                if let Some(i) = instance {
                    write!(f, "instance `{i}`: ")?;
                }
                write!(f, "{source}")
            }
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Io { source, .. } => Some(source),
            Error::Scene { source, .. } => Some(source.as_ref()),
            _ => None,
        }
    }
}

pub fn io_err(path: &std::path::Path) -> impl FnOnce(std::io::Error) -> Error + '_ {
    move |source| Error::Io {
        path: path.to_path_buf(),
        source,
    }
}
