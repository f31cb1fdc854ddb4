#![no_main]
//! Fuzzes the USD text importer: see tests/hostile/formats/usda.rs for what is checked.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    tress_fuzz::formats::usda::check(data);
});
