#![no_main]
//! Fuzzes the exr reader: see tests/hostile/formats/exr.rs for what is checked.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    tress_fuzz::formats::exr::check(data);
});
