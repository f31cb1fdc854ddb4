#![no_main]
//! Fuzzes the obj reader: see tests/hostile/formats/obj.rs for what is checked.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    tress_fuzz::formats::obj::check(data);
});
