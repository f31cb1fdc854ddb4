#![no_main]
//! Fuzzes the scene reader: see tests/hostile/formats/scene.rs for what is checked.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    tress_fuzz::formats::scene::check(data);
});
