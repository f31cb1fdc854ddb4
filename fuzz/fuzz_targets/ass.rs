#![no_main]
//! Fuzzes the ass importer: see tests/hostile/formats/ass.rs for what is checked.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    tress_fuzz::formats::ass::check(data);
});
