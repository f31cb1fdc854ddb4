#![no_main]
//! Fuzzes the pbrt importer: see tests/hostile/formats/pbrt.rs for what is checked.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    tress_fuzz::formats::pbrt::check(data);
});
