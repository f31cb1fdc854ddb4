#![no_main]
//! Fuzzes the Maya ASCII importer: see tests/hostile/formats/ma.rs for what is checked.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    tress_fuzz::formats::ma::check(data);
});
