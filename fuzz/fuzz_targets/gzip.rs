#![no_main]
//! Fuzzes the gzip importer: see tests/hostile/formats/gzip.rs for what is checked.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    tress_fuzz::formats::gzip::check(data);
});
