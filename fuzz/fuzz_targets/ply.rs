#![no_main]
//! Fuzzes the ply reader: see tests/hostile/formats/ply.rs for what is checked.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    tress_fuzz::formats::ply::check(data);
});
