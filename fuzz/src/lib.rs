//! The formats and checks the fuzz targets run: the same files as the proptests in
//! `tests/hostile.rs`, so both exercise one definition of "rejected or usable".

#[path = "../../tests/hostile/formats/mod.rs"]
pub mod formats;
