#![no_main]
//! Fuzzes the hair reader: see tests/hostile/formats/hair.rs for what is checked.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    tress_fuzz::formats::hair::check(data);
});
