//! weft render runtime (work in progress).
