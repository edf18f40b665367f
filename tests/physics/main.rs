//! The physics of the shipped materials, each against a reference written
//! from its paper or a peer's published formulas (not from weft's WGSL):
//! furnaces, fibre and cloth BSDFs, films, glints, skin, eyes, faces, fur,
//! and tier ladders (the stability sweep is its own binary, `stability`).

mod energy;
mod eye;
mod face;
mod fur;
mod glints;
mod hair_furnace;
mod ladders;
mod laser_film;
mod microcylinder;
mod silk_energy;
mod skin;
