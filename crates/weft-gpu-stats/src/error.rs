//! The crate's error: every failure names what is missing or what failed,
//! and how to fix it where there is a fix.

use std::fmt;

/// What went wrong while collecting statistics.
#[derive(Debug)]
pub enum Error {
    /// No RADV ICD manifest in the folders searched (Mesa's AMD Vulkan driver is not installed).
    RadvMissing {
        /// The folders searched, in order.
        searched: Vec<std::path::PathBuf>,
    },
    /// The Vulkan loader (`libvulkan.so.1`) could not be loaded.
    LoaderMissing(String),
    /// A Vulkan call failed.
    Vulkan {
        /// What was being done.
        what: String,
        /// The driver's result code.
        result: ash::vk::Result,
    },
    /// The metadata or a shader file could not be read or does not say what is needed.
    Input(String),
    /// The device or driver does not offer something a pipeline needs.
    Unsupported(String),
    /// The child process that compiles one family failed.
    Worker(String),
}

/// The package that provides RADV on Debian and Ubuntu (as `.ci/run` installs it).
pub const RADV_PACKAGE: &str = "mesa-vulkan-drivers";

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::RadvMissing { searched } => {
                let dirs: Vec<String> = searched.iter().map(|d| d.display().to_string()).collect();
                write!(
                    f,
                    "RADV, Mesa's Vulkan driver for AMD GPUs, is not installed: no radeon_icd*.json \
                     in {}. Install the package `{RADV_PACKAGE}` (Debian/Ubuntu: \
                     `apt-get install {RADV_PACKAGE}`; Fedora: mesa-vulkan-drivers; Arch: \
                     vulkan-radeon). No AMD GPU is needed: its null device compiles without one.",
                    if dirs.is_empty() {
                        "(no folder)".to_string()
                    } else {
                        dirs.join(", ")
                    }
                )
            }
            Error::LoaderMissing(e) => write!(
                f,
                "the Vulkan loader could not be loaded ({e}): install the package `libvulkan1` \
                 (and `{RADV_PACKAGE}` for RADV)"
            ),
            Error::Vulkan { what, result } => write!(f, "{what}: {result}"),
            Error::Input(m) | Error::Unsupported(m) | Error::Worker(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for Error {}

/// Shorthand for the crate's results.
pub type Result<T> = std::result::Result<T, Error>;

/// Maps a Vulkan result to [`Error::Vulkan`] saying what was being done.
pub(crate) fn vk_err(what: impl Into<String>) -> impl FnOnce(ash::vk::Result) -> Error {
    let what = what.into();
    move |result| Error::Vulkan { what, result }
}
