//! A GPU family's names: the one weft's reports, `gpu-model.json` and
//! `[scene] gpu_family` use, and the ones RADV accepts in `RADV_FORCE_FAMILY`,
//! which changed between Mesa versions.
//!
//! Mesa 22.3 (Debian 12) calls RDNA3's first chip `gfx1100`; later releases
//! call it `navi31`. Each RADV aborts on the other's name ("radv: Unknown family"),
//! so the parent tries the spellings in order (see [`crate::worker::run_child`])
//! and the figures keep weft's name on every Mesa. The table of spellings is
//! `weft_meta::scene::GPU_FAMILY_SPELLINGS`, which scene files read too.

use weft_meta::scene::GPU_FAMILY_SPELLINGS;

/// The `RADV_FORCE_FAMILY` values that select `family`, older Mesa first. A
/// family Mesa never renamed is its own only spelling.
pub fn radv_spellings(family: &str) -> Vec<&str> {
    GPU_FAMILY_SPELLINGS
        .iter()
        .find(|(_, all)| all.contains(&family))
        .map_or_else(|| vec![family], |(_, all)| all.to_vec())
}

/// weft's name of the family RADV calls `family`: `navi31` is `gfx1100`;
/// every other name is weft's as it is.
pub use weft_meta::scene::weft_gpu_family as weft_name;

/// Whether a worker's messages say that RADV does not know the family name it
/// was given (its null winsys prints this, then aborts).
pub fn is_unknown_family(stderr: &str) -> bool {
    stderr.contains("Unknown family")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rdna3_has_both_mesa_spellings_and_others_their_own() {
        assert_eq!(radv_spellings("gfx1100"), ["gfx1100", "navi31"]);
        assert_eq!(radv_spellings("navi31"), ["gfx1100", "navi31"]);
        assert_eq!(radv_spellings("navi21"), ["navi21"]);
        assert_eq!(weft_name("navi31"), "gfx1100");
        assert_eq!(weft_name("navi21"), "navi21");
        assert!(is_unknown_family("radv: Unknown family: gfx1100\n"));
        assert!(!is_unknown_family("compiling failed"));
    }
}
