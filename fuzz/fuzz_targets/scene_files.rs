#![no_main]
//! Fuzzes the whole scenes (a scene file and the files it names): see tests/hostile/formats/scene_files.rs for what is checked.

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    tress_fuzz::formats::scene_files::check(data);
});
