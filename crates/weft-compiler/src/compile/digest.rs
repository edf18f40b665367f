//! Content hashes: the lower-case hex SHA-256 that metadata, caches and
//! shards state for every file and table they name.

use sha2::{Digest, Sha256};

pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}
